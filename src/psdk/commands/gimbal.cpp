#include "k40t_driver/psdk/commands/gimbal.h"

namespace k40t::psdk {

const char* to_string(GimbalStateMode mode) {
  switch (mode) {
    case GimbalStateMode::kFree:
      return "free";
    case GimbalStateMode::kFollowing:
      return "following";
    case GimbalStateMode::kFpv:
      return "fpv";
  }
  return nullptr;
}

const char* to_string(GimbalMode mode) {
  switch (mode) {
    case GimbalMode::kFree:
      return "free";
    case GimbalMode::kFpv:
      return "fpv";
    case GimbalMode::kFollowing:
      return "following";
  }
  return nullptr;
}

GimbalStateMode to_state_mode(GimbalMode mode) {
  switch (mode) {
    case GimbalMode::kFpv:
      return GimbalStateMode::kFpv;
    case GimbalMode::kFollowing:
      return GimbalStateMode::kFollowing;
    case GimbalMode::kFree:
      break;
  }
  return GimbalStateMode::kFree;
}

const char* to_string(GimbalControlAction action) {
  switch (action) {
    case GimbalControlAction::kStop:
      return "stop";
    case GimbalControlAction::kControl:
      return "control";
  }
  return nullptr;
}

const char* to_string(CalibrationStatus status) {
  switch (status) {
    case CalibrationStatus::kComplete:
      return "complete";
    case CalibrationStatus::kInProgress:
      return "in_progress";
    case CalibrationStatus::kFailed:
      return "failed";
  }
  return nullptr;
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
