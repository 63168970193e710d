#include "k40t_driver/psdk/commands/camera_capture.h"
#include "k40t_driver/psdk/commands/camera_lens.h"

#include "k40t_driver/codec/enum_names.h"

namespace k40t::psdk {

const char* to_string(CameraWorkMode mode) {
  return consecutive_name(mode, 0, {"shoot_photo", "record_video"});
}

const char* to_string(ShootPhotoAction action) {
  return consecutive_name(action, 0, {"stop", "start"});
}

const char* to_string(ShootPhotoType type) {
  return name_in({{ShootPhotoType::kSingle, "single"},
                  {ShootPhotoType::kBurst, "burst"},
                  {ShootPhotoType::kInterval, "interval"}},
                 type, nullptr);
}

const char* to_string(RecordAction action) {
  return consecutive_name(action, 0, {"stop", "start"});
}

const char* to_string(MeteringMode mode) {
  return consecutive_name(mode, 0, {"center", "average", "spot"});
}

const char* to_string(FocusMode mode) {
  return consecutive_name(mode, 0, {"manual", "auto"});
}

const char* to_string(ZoomSpeed speed) {
  return consecutive_name(
      speed, 72,
      {"slowest", "slow", "moderately_slow", "normal", "moderately_fast", "fast", "fastest"});
}

const char* to_string(ZoomDirection direction) {
  return consecutive_name(direction, 0, {"out", "in"});
}

Status OpticalZoomSpecValue::validate() const {
  if (min_focal_length_mm > max_focal_length_mm) {
    return Status::fail("field 'min_focal_length_mm' must not exceed max_focal_length_mm");
  }
  return Status::ok();
}

}  // namespace k40t::psdk
