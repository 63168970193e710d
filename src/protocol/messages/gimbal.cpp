#include "k40t_driver/protocol/messages/gimbal.h"

#include <cmath>
#include <string>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::protocol {

// ---- enums ----------------------------------------------------------------------------------
const char* to_string(GimbalLinkState state) {
  return consecutive_name(state, 0, {"normal", "abnormal"});
}

const char* to_string(GimbalUpgradeState state) {
  return consecutive_name(state, 0,
                          {"normal", "kernel upgrade incomplete", "firmware upgrade incomplete"});
}

const char* to_string(GimbalStabilisationState state) {
  return consecutive_name(state, 0, {"off", "stabilising", "failed", "feature lost"});
}

const char* to_string(GimbalMode mode) {
  return consecutive_name(mode, 0, {"none", "centre", "look down"});
}

const char* to_string(GimbalYawDirection direction) {
  return consecutive_name(direction, 0, {"left", "right", "stop"});
}

const char* to_string(GimbalPitchDirection direction) {
  return consecutive_name(direction, 0, {"up", "down", "stop"});
}

const char* to_string(GimbalAimLens lens) {
  return consecutive_name(lens, 0, {"telephoto", "wide-angle", "thermal"});
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
