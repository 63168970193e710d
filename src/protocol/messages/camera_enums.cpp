#include "k40t_driver/protocol/messages/camera_enums.h"

#include "k40t_driver/protocol/cfg_enum_names.h"

namespace k40t::protocol {

// The names of the settings' codes come from cfg/setting_enums.txt (cfg_enum_names.h); the other
// texts follow the document's wording (Chinese original, sections 3.2.1.1 and 3.2.4).

const char* to_string(CaptureMode v) {
  return cfg_enums::constant_of(cfg_enums::camera_mode, static_cast<int>(v), "mode_");
}

const char* to_string(ReportedStreamResolution v) {
  switch (v) {
    case ReportedStreamResolution::k1080p30:
      return "1080P30";
    case ReportedStreamResolution::k720p30:
      return "720P30";
  }
  return nullptr;
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
  switch (v) {
    case StreamBitrate::k1Mbps:
      return 1.0;
    case StreamBitrate::k1_5Mbps:
      return 1.5;
    case StreamBitrate::k2Mbps:
      return 2.0;
    case StreamBitrate::k4Mbps:
      return 4.0;
    case StreamBitrate::k8Mbps:
      return 8.0;
    case StreamBitrate::k12Mbps:
      return 12.0;
  }
  return 0.0;
}

const char* to_string(PhotoMode v) {
  return cfg_enums::description_of(cfg_enums::photo_mode, static_cast<int>(v));
}

const char* to_string(SdCardState v) {
  switch (v) {
    case SdCardState::kNormal:
      return "normal";
    case SdCardState::kAbnormal:
      return "abnormal card";
    case SdCardState::kSlow:
      return "slow card";
    case SdCardState::kMissing:
      return "no SD card";
    case SdCardState::kFull:
      return "SD card full";
    case SdCardState::kFormatError:
      return "SD card format error";
  }
  return nullptr;
}

const char* to_string(CameraUpgradeState v) {
  switch (v) {
    case CameraUpgradeState::kSucceeded:
      return "upgrade or repair succeeded";
    case CameraUpgradeState::kFailed:
      return "upgrade or repair failed";
    case CameraUpgradeState::kUpgrading:
      return "upgrading";
    case CameraUpgradeState::kRepairing:
      return "repairing";
  }
  return nullptr;
}

const char* to_string(PhotoLensMode v) {
  switch (v) {
    case PhotoLensMode::kDefault:
      return "default (infrared + visible)";
    case PhotoLensMode::kInfrared:
      return "infrared";
    case PhotoLensMode::kVisible:
      return "visible";
    case PhotoLensMode::kInfraredAndVisible:
      return "infrared + visible";
  }
  return nullptr;
}

const char* to_string(RecordLensMode v) {
  switch (v) {
    case RecordLensMode::kDefault:
      return "default (infrared + visible)";
    case RecordLensMode::kInfrared:
      return "infrared";
    case RecordLensMode::kVisible:
      return "visible";
    case RecordLensMode::kInfraredAndVisible:
      return "infrared + visible";
    case RecordLensMode::kStreamCapture:
      return "video stream (1920x1080)";
  }
  return nullptr;
}

const char* to_string(PhotoAction v) {
  switch (v) {
    case PhotoAction::kStart:
      return "single shot / start";
    case PhotoAction::kStop:
      return "stop (burst only)";
  }
  return nullptr;
}

const char* to_string(RecordAction v) {
  switch (v) {
    case RecordAction::kStart:
      return "start recording";
    case RecordAction::kStop:
      return "stop recording";
  }
  return nullptr;
}

const char* to_string(ZoomCommand v) {
  switch (v) {
    case ZoomCommand::kZoomIn:
      return "continuous zoom in";
    case ZoomCommand::kZoomOut:
      return "continuous zoom out";
    case ZoomCommand::kStop:
      return "stop zooming";
    case ZoomCommand::kStepIn:
      return "zoom in one step";
    case ZoomCommand::kStepOut:
      return "zoom out one step";
  }
  return nullptr;
}

const char* to_string(ReshootResolution v) {
  switch (v) {
    case ReshootResolution::k8000x6000:
      return "8000x6000";
    case ReshootResolution::k4000x3000:
      return "4000x3000";
    case ReshootResolution::k5160x3890:
      return "5160x3890";
    case ReshootResolution::k5664x4248:
      return "5664x4248";
  }
  return nullptr;
}

const char* to_string(IpMode v) {
  switch (v) {
    case IpMode::kStatic:
      return "static";
    case IpMode::kDhcp:
      return "dynamic (DHCP)";
  }
  return nullptr;
}

const char* to_string(FocusCommand v) {
  switch (v) {
    case FocusCommand::kAuto:
      return "auto focus";
    case FocusCommand::kFinePlus:
      return "manual fine focus +";
    case FocusCommand::kFineMinus:
      return "manual fine focus -";
    case FocusCommand::kFineStop:
      return "stop manual fine focus";
    case FocusCommand::kArea:
      return "area auto focus";
    case FocusCommand::kOneShot:
      return "one-touch focus";
    case FocusCommand::kAutoAfterZoomOn:
      return "auto focus after zoom on";
    case FocusCommand::kAutoAfterZoomOff:
      return "auto focus after zoom off";
  }
  return nullptr;
}

const char* to_string(FeatureSwitch v) {
  switch (v) {
    case FeatureSwitch::kOn:
      return "on";
    case FeatureSwitch::kOff:
      return "off";
  }
  return nullptr;
}

const char* to_string(PhotoState v) {
  switch (v) {
    case PhotoState::kDone:
      return "photo taken";
    case PhotoState::kSingleShot:
      return "single shot in progress";
    case PhotoState::kBurst:
      return "burst in progress";
    case PhotoState::kTimeLapse:
      return "time-lapse in progress";
    case PhotoState::kStopped:
      return "stopped";
    case PhotoState::kSingleShot5:
      return "single shot in progress (code 5)";
    case PhotoState::kFailed:
      return "photo failed";
    case PhotoState::kNoSdCard:
      return "no SD card";
    case PhotoState::kSdFull:
      return "SD card full";
    case PhotoState::kSdAbnormal:
      return "abnormal card";
    case PhotoState::kSdSlow:
      return "slow card";
    case PhotoState::kSdFormatError:
      return "SD card format error";
  }
  return nullptr;
}

const char* to_string(ReshootState v) {
  switch (v) {
    case ReshootState::kDone:
      return "photo taken";
    case ReshootState::kBurst:
      return "burst in progress";
    case ReshootState::kContinuous:
      return "continuous shooting in progress";
    case ReshootState::kTimeLapse:
      return "time-lapse in progress";
    case ReshootState::kStopped:
      return "stopped";
    case ReshootState::kSingleShot:
      return "single shot in progress";
    case ReshootState::kFailed:
      return "photo failed";
    case ReshootState::kNoSdCard:
      return "no SD card";
    case ReshootState::kSdFull:
      return "SD card full";
    case ReshootState::kSdAbnormal:
      return "abnormal card";
    case ReshootState::kSdSlow:
      return "slow card";
    case ReshootState::kSdFormatError:
      return "SD card format error";
    case ReshootState::kReshooting:
      return "precise re-shoot in progress";
  }
  return nullptr;
}

const char* to_string(RecordState v) {
  switch (v) {
    case RecordState::kStopped:
      return "stopped";
    case RecordState::kRecording:
      return "recording";
    case RecordState::kTimeLapseWaiting:
      return "waiting for time-lapse recording";
    case RecordState::kTimeLapseRecording:
      return "time-lapse recording";
    case RecordState::kNoSdCard:
      return "no SD card";
    case RecordState::kSdFull:
      return "SD card full";
    case RecordState::kSdAbnormal:
      return "abnormal card";
    case RecordState::kSdSlow:
      return "slow card";
    case RecordState::kSdFormatError:
      return "SD card format error";
  }
  return nullptr;
}

const char* to_string(ZoomProgress v) {
  switch (v) {
    case ZoomProgress::kDone:
      return "zoom done";
    case ZoomProgress::kZooming:
      return "zooming";
  }
  return nullptr;
}

const char* to_string(TfUpgradeState v) {
  switch (v) {
    case TfUpgradeState::kSucceeded:
      return "upgrade succeeded";
    case TfUpgradeState::kUpgrading:
      return "upgrading";
    case TfUpgradeState::kFailed:
      return "upgrade failed";
  }
  return nullptr;
}

const char* to_string(SdFormatState v) {
  switch (v) {
    case SdFormatState::kDone:
      return "format done";
    case SdFormatState::kFormatting:
      return "formatting";
    case SdFormatState::kFailed:
      return "format failed";
    case SdFormatState::kUnavailable:
      return "SD card unavailable";
  }
  return nullptr;
}

const char* to_string(GpsFixStatus v) {
  switch (v) {
    case GpsFixStatus::kNotConnected:
      return "GPS not connected";
    case GpsFixStatus::kNoFix:
      return "no fix";
    case GpsFixStatus::kFix2d:
      return "2D fix";
    case GpsFixStatus::kFix3d:
      return "3D fix";
    case GpsFixStatus::kDgps:
      return "3D fix with DGPS/SBAS";
    case GpsFixStatus::kRtkFloat:
      return "RTK float";
    case GpsFixStatus::kRtkFixed:
      return "RTK fixed";
    case GpsFixStatus::kStatic:
      return "static (base station)";
    case GpsFixStatus::kPpp:
      return "PPP 3D fix";
  }
  return nullptr;
}

}  // namespace k40t::protocol
