#include "k40t_driver/protocol/messages/camera_reports.h"

#include "camera_codec.h"

namespace k40t::protocol {

using camera_codec::get_code;
using camera_codec::put_code;

// ---- 0x000003 ------------------------------------------------------------------------------
Status CameraSystemStatus::validate() const {
  return first_failure(check_enum("capture_mode", capture_mode),
                       check_enum("stream_resolution", stream_resolution),
                       check_enum("encoding", encoding), check_enum("image_mode", image_mode),
                       check_enum("bitrate", bitrate), check_enum("photo_mode", photo_mode),
                       camera_codec::check_photo_settings(time_lapse_interval_s, burst_count),
                       check_enum("sd_state", sd_state),
                       check_range("sd_total_mb", sd_total_mb, 0.0, kSdCapacityMaxMb, "MB"),
                       check_range("sd_free_mb", sd_free_mb, 0.0, kSdCapacityMaxMb, "MB"),
                       check_range("sd_used_mb", sd_used_mb, 0.0, kSdCapacityMaxMb, "MB"));
}

void CameraSystemStatus::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, capture_mode);
  put_code(w, stream_resolution);
  put_code(w, encoding);
  put_code(w, image_mode);
  put_code(w, bitrate);
  put_code(w, photo_mode);
  w.u8(time_lapse_interval_s);
  w.u8(burst_count);
  put_code(w, sd_state);
  for (double mb : {sd_total_mb, sd_free_mb, sd_used_mb}) {
    w.u16(to_wire<uint16_t>(mb, 1.0 / kSdCapacityUnitMb));
  }
  w.zeros(1);
}

Status CameraSystemStatus::decode(ByteReader& r, const CodecOptions&) {
  capture_mode = get_code<CaptureMode>(r);
  stream_resolution = get_code<ReportedStreamResolution>(r);
  encoding = get_code<VideoEncoding>(r);
  image_mode = get_code<ImageMode>(r);
  bitrate = get_code<StreamBitrate>(r);
  photo_mode = get_code<PhotoMode>(r);
  time_lapse_interval_s = r.u8();
  burst_count = r.u8();
  sd_state = get_code<SdCardState>(r);
  for (double* mb : {&sd_total_mb, &sd_free_mb, &sd_used_mb}) *mb = r.u16() * kSdCapacityUnitMb;
  return Status::ok();
}

// ---- 0x000008 ------------------------------------------------------------------------------
Status CameraUpgradeStatus::validate() const {
  return first_failure(check_enum("state", state),
                       camera_codec::check_int("progress_percent", progress_percent, 0, 100, "%"));
}

void CameraUpgradeStatus::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, state);
  w.u8(progress_percent);
  w.zeros(1);
}

Status CameraUpgradeStatus::decode(ByteReader& r, const CodecOptions&) {
  state = get_code<CameraUpgradeState>(r);
  progress_percent = r.u8();
  return Status::ok();
}

}  // namespace k40t::protocol
