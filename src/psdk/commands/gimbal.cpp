#include "k40t_driver/psdk/commands/gimbal.h"

#include "k40t_driver/codec/enum_names.h"

namespace k40t::psdk {

const char* to_string(GimbalStateMode mode) {
  return consecutive_name(mode, 0, {"free", "following", "fpv"});
}

const char* to_string(GimbalMode mode) {
  return consecutive_name(mode, 0, {"free", "fpv", "following"});
}

GimbalStateMode to_state_mode(GimbalMode mode) {
  if (mode == GimbalMode::kFpv) return GimbalStateMode::kFpv;
  if (mode == GimbalMode::kFollowing) return GimbalStateMode::kFollowing;
  return GimbalStateMode::kFree;
}

const char* to_string(GimbalControlAction action) {
  return consecutive_name(action, 0, {"stop", "control"});
}

const char* to_string(CalibrationStatus status) {
  return consecutive_name(status, 0, {"complete", "in_progress", "failed"});
}

Status ControlGimbalSpeed::validate() const {
  return first_failure(check_real("pitch_rate_deg_s", pitch_rate_deg_s, -kMaxGimbalRateDegS,
                                  kMaxGimbalRateDegS, "deg/s"),
                       check_real("roll_rate_deg_s", roll_rate_deg_s, -kMaxGimbalRateDegS,
                                  kMaxGimbalRateDegS, "deg/s"),
                       check_real("yaw_rate_deg_s", yaw_rate_deg_s, -kMaxGimbalRateDegS,
                                  kMaxGimbalRateDegS, "deg/s"));
}

}  // namespace k40t::psdk
