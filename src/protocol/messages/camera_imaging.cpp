#include "k40t_driver/protocol/messages/camera_imaging.h"

#include "camera_codec.h"

namespace k40t::protocol {

// ---- 0x00030A ------------------------------------------------------------------------------
Status StreamResolutionRequest::validate() const {
  if (resolution != StreamResolution::k720p30) return ByteSettingRequest::validate();
  return Status::fail(
      "field 'resolution': 2 (720P30) is not supported by the pod (section 3.2.4.9); use 1 "
      "(1080P30)");
}

// ---- 0x000313 ------------------------------------------------------------------------------
Status FocusRequest::extra_checks() const {
  if (command != FocusCommand::kArea) return Status::ok();
  return first_failure(camera_codec::check_int("area_right_px", area_right_px, area_left_px + 1,
                                               kStreamWidthPx, "px"),
                       camera_codec::check_int("area_bottom_px", area_bottom_px, area_top_px + 1,
                                               kStreamHeightPx, "px"));
}

// ---- 0x000324 ------------------------------------------------------------------------------
Status BoxTrackingRequest::extra_checks() const {
  // The layout has checked x and y, so the width/height bounds below are never negative.
  return first_failure(camera_codec::check_int("width_px", width_px, 0, kStreamWidthPx - x_px,
                                               "px (x_px + width_px <= 1920)"),
                       camera_codec::check_int("height_px", height_px, 0, kStreamHeightPx - y_px,
                                               "px (y_px + height_px <= 1080)"));
}

}  // namespace k40t::protocol
