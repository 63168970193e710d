#include "k40t_driver/protocol/messages/camera_enums.h"

#include "k40t_driver/protocol/cfg_enum_names.h"

namespace k40t::protocol {

// The names of the settings' codes come from cfg/setting_enums.txt (cfg_enum_names.h); the other
// texts follow the document's wording (Chinese original, sections 3.2.1.1 and 3.2.4), by code
// from the first.

const char* to_string(CaptureMode v) {
  return cfg_enums::constant_of(cfg_enums::camera_mode, static_cast<int>(v), "mode_");
}

const char* to_string(ReportedStreamResolution v) {
  return consecutive_name(v, 0, {"1080P30", "720P30"});
}

const char* to_string(StreamResolution v) {
  return cfg_enums::constant_of(cfg_enums::stream_resolution, static_cast<int>(v), "stream_");
}

const char* to_string(VideoEncoding v) {
  return cfg_enums::description_of(cfg_enums::stream_encoding, static_cast<int>(v));
}

const char* to_string(ImageMode v) {
  return cfg_enums::constant_of(cfg_enums::image_mode, static_cast<int>(v), "image_");
}

const char* to_string(StreamBitrate v) {
  return cfg_enums::description_of(cfg_enums::stream_bitrate, static_cast<int>(v));
}

double bitrate_mbps(StreamBitrate v) {
  return by_code(v, 1, {1.0, 1.5, 2.0, 4.0, 8.0, 12.0}, 0.0);
}

const char* to_string(PhotoMode v) {
  return cfg_enums::constant_of(cfg_enums::photo_mode, static_cast<int>(v), "photo_");
}

const char* to_string(SdCardState v) {
  return consecutive_name(v, 0,
                          {"normal", "abnormal card", "slow card", "no SD card", "SD card full",
                           "SD card format error"});
}

const char* to_string(CameraUpgradeState v) {
  return consecutive_name(
      v, 0, {"upgrade or repair succeeded", "upgrade or repair failed", "upgrading", "repairing"});
}

const char* to_string(PhotoLensMode v) {
  return consecutive_name(
      v, 0, {"default (infrared + visible)", "infrared", "visible", "infrared + visible"});
}

const char* to_string(RecordLensMode v) {
  return consecutive_name(v, 0,
                          {"default (infrared + visible)", "infrared", "visible",
                           "infrared + visible", "video stream (1920x1080)"});
}

const char* to_string(PhotoAction v) {
  return consecutive_name(v, 0, {"single shot / start", "stop (burst only)"});
}

const char* to_string(RecordAction v) {
  return consecutive_name(v, 1, {"start recording", "stop recording"});
}

const char* to_string(ZoomCommand v) {
  return consecutive_name(v, 0,
                          {"continuous zoom in", "continuous zoom out", "stop zooming",
                           "zoom in one step", "zoom out one step"});
}

const char* to_string(ReshootResolution v) {
  return consecutive_name(v, 0x14, {"8000x6000", "4000x3000", "5160x3890", "5664x4248"});
}

const char* to_string(IpMode v) {
  return consecutive_name(v, 0, {"static", "dynamic (DHCP)"});
}

const char* to_string(FocusCommand v) {
  return consecutive_name(v, 0,
                          {"auto focus", "manual fine focus +", "manual fine focus -",
                           "stop manual fine focus", "area auto focus", "one-touch focus",
                           "auto focus after zoom on", "auto focus after zoom off"});
}

const char* to_string(FeatureSwitch v) {
  return consecutive_name(v, 1, {"on", "off"});
}

const char* to_string(PhotoState v) {
  return consecutive_name(
      v, 0,
      {"photo taken", "single shot in progress", "burst in progress", "time-lapse in progress",
       "stopped", "single shot in progress (code 5)", "photo failed", "no SD card", "SD card full",
       "abnormal card", "slow card", "SD card format error"});
}

const char* to_string(ReshootState v) {
  return consecutive_name(v, 0,
                          {"photo taken", "burst in progress", "continuous shooting in progress",
                           "time-lapse in progress", "stopped", "single shot in progress",
                           "photo failed", "no SD card", "SD card full", "abnormal card",
                           "slow card", "SD card format error", "precise re-shoot in progress"});
}

const char* to_string(RecordState v) {
  return consecutive_name(
      v, 0,
      {"stopped", "recording", "waiting for time-lapse recording", "time-lapse recording",
       "no SD card", "SD card full", "abnormal card", "slow card", "SD card format error"});
}

const char* to_string(ZoomProgress v) {
  return consecutive_name(v, 0, {"zoom done", "zooming"});
}

const char* to_string(TfUpgradeState v) {
  return consecutive_name(v, 0, {"upgrade succeeded", "upgrading", "upgrade failed"});
}

const char* to_string(SdFormatState v) {
  return consecutive_name(v, 0,
                          {"format done", "formatting", "format failed", "SD card unavailable"});
}

const char* to_string(GpsFixStatus v) {
  return consecutive_name(
      v, 0,
      {"GPS not connected", "no fix", "2D fix", "3D fix", "3D fix with DGPS/SBAS", "RTK float",
       "RTK fixed", "static (base station)", "PPP 3D fix"});
}

}  // namespace k40t::protocol
