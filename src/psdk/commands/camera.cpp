#include "k40t_driver/psdk/commands/camera_capture.h"
#include "k40t_driver/psdk/commands/camera_lens.h"

namespace k40t::psdk {

const char* to_string(CameraWorkMode mode) {
  switch (mode) {
    case CameraWorkMode::kShootPhoto:
      return "shoot_photo";
    case CameraWorkMode::kRecordVideo:
      return "record_video";
  }
  return nullptr;
}

const char* to_string(ShootPhotoAction action) {
  switch (action) {
    case ShootPhotoAction::kStop:
      return "stop";
    case ShootPhotoAction::kStart:
      return "start";
  }
  return nullptr;
}

const char* to_string(ShootPhotoType type) {
  switch (type) {
    case ShootPhotoType::kSingle:
      return "single";
    case ShootPhotoType::kBurst:
      return "burst";
    case ShootPhotoType::kInterval:
      return "interval";
  }
  return nullptr;
}

const char* to_string(RecordAction action) {
  switch (action) {
    case RecordAction::kStop:
      return "stop";
    case RecordAction::kStart:
      return "start";
  }
  return nullptr;
}

const char* to_string(MeteringMode mode) {
  switch (mode) {
    case MeteringMode::kCenter:
      return "center";
    case MeteringMode::kAverage:
      return "average";
    case MeteringMode::kSpot:
      return "spot";
  }
  return nullptr;
}

const char* to_string(FocusMode mode) {
  switch (mode) {
    case FocusMode::kManual:
      return "manual";
    case FocusMode::kAuto:
      return "auto";
  }
  return nullptr;
}

const char* to_string(ZoomSpeed speed) {
  switch (speed) {
    case ZoomSpeed::kSlowest:
      return "slowest";
    case ZoomSpeed::kSlow:
      return "slow";
    case ZoomSpeed::kModeratelySlow:
      return "moderately_slow";
    case ZoomSpeed::kNormal:
      return "normal";
    case ZoomSpeed::kModeratelyFast:
      return "moderately_fast";
    case ZoomSpeed::kFast:
      return "fast";
    case ZoomSpeed::kFastest:
      return "fastest";
  }
  return nullptr;
}

const char* to_string(ZoomDirection direction) {
  switch (direction) {
    case ZoomDirection::kOut:
      return "out";
    case ZoomDirection::kIn:
      return "in";
  }
  return nullptr;
}

Status OpticalZoomSpecAck::validate() const {
  if (min_focal_length_mm > max_focal_length_mm) {
    return Status::fail("field 'min_focal_length_mm' must not exceed max_focal_length_mm");
  }
  return Status::ok();
}

}  // namespace k40t::psdk
