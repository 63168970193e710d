#include "k40t_driver/protocol/messages/gimbal.h"

#include <cmath>
#include <string>

namespace k40t::protocol {

// ---- enums ----------------------------------------------------------------------------------
const char* to_string(GimbalLinkState state) {
  switch (state) {
    case GimbalLinkState::kNormal:
      return "normal";
    case GimbalLinkState::kAbnormal:
      return "abnormal";
  }
  return nullptr;
}

const char* to_string(GimbalUpgradeState state) {
  switch (state) {
    case GimbalUpgradeState::kNormal:
      return "normal";
    case GimbalUpgradeState::kKernelUpgradeIncomplete:
      return "kernel upgrade incomplete";
    case GimbalUpgradeState::kFirmwareUpgradeIncomplete:
      return "firmware upgrade incomplete";
  }
  return nullptr;
}

const char* to_string(GimbalStabilisationState state) {
  switch (state) {
    case GimbalStabilisationState::kOff:
      return "off";
    case GimbalStabilisationState::kStabilising:
      return "stabilising";
    case GimbalStabilisationState::kFailed:
      return "failed";
    case GimbalStabilisationState::kFeatureLost:
      return "feature lost";
  }
  return nullptr;
}

const char* to_string(GimbalMode mode) {
  switch (mode) {
    case GimbalMode::kNone:
      return "none";
    case GimbalMode::kCentre:
      return "centre";
    case GimbalMode::kLookDown:
      return "look down";
  }
  return nullptr;
}

const char* to_string(GimbalYawDirection direction) {
  switch (direction) {
    case GimbalYawDirection::kLeft:
      return "left";
    case GimbalYawDirection::kRight:
      return "right";
    case GimbalYawDirection::kStop:
      return "stop";
  }
  return nullptr;
}

const char* to_string(GimbalPitchDirection direction) {
  switch (direction) {
    case GimbalPitchDirection::kUp:
      return "up";
    case GimbalPitchDirection::kDown:
      return "down";
    case GimbalPitchDirection::kStop:
      return "stop";
  }
  return nullptr;
}

const char* to_string(GimbalAimLens lens) {
  switch (lens) {
    case GimbalAimLens::kTele:
      return "telephoto";
    case GimbalAimLens::kWide:
      return "wide-angle";
    case GimbalAimLens::kThermal:
      return "thermal";
  }
  return nullptr;
}

// ---- 0x010018 -------------------------------------------------------------------------------
Status GimbalVersionAck::finish_decode(size_t payload_size) const {
  constexpr size_t kVersionSize = kSize - 1;  // the reserved last byte is optional
  return code_alone_or_at_least(kName, kId, payload_size, kVersionSize);
}

// ---- 0x00002C -------------------------------------------------------------------------------
Status check_aim_zoom(const char* field, GimbalAimLens lens, double zoom_x) {
  const char* lens_name = to_string(lens);
  if (lens_name == nullptr) return Status::ok();
  if (lens == GimbalAimLens::kTele)
    return check_range(field, zoom_x, 3.5, 160.0, "x for the telephoto lens");
  const std::string unit = std::string("x (whole numbers) for the ") + lens_name + " lens";
  const Status range = check_range(field, zoom_x, 1.0, 8.0, unit.c_str());
  if (range && zoom_x != std::floor(zoom_x)) {
    return Status::fail(std::string("field '") + field + "' must be a whole number 1..8 for the " +
                        lens_name + " lens, got " + std::to_string(zoom_x));
  }
  return range;
}

}  // namespace k40t::protocol
