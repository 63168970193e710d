// The bridge's gimbal commands (0x05). Angles: DJI signs (pitch up, yaw right, roll right side
// down positive) against the pod's REP 103 joint angles (pod_port.h).
#include <algorithm>
#include <cmath>

#include "k40t_driver/skyport/gimbal_frame.h"
#include "k40t_driver/skyport/skyport_bridge.h"

namespace k40t::driver::skyport {

using namespace psdk;
using detail::refused;

namespace {
constexpr double kDegPerRad = 180.0 / M_PI;
// The pod's roll only stabilises: a roll command (angle or rate) beyond this is refused.
constexpr double kRollDeadbandDeg = 0.5;
}  // namespace

CalibrationProgressAck SkyportBridge::calibration_progress(const PodSnapshot& s) const {
  std::optional<Calibration> run;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    run = calibration_;
  }
  // Nothing calibrated through the bridge: no progress to report (not "complete").
  if (!run) return refused<CalibrationProgressAck>(AckCode::kError);
  CalibrationProgressAck ack;
  if (s.repair_status_count > run->repair_reports_before) {
    // The pod's repair report (0x000008) since the calibration started.
    switch (s.repair_state) {
      case kRepairSucceeded:
        ack.progress_percent = 100;
        ack.status = CalibrationStatus::kComplete;
        return ack;
      case kRepairFailed:
        ack.progress_percent = std::min<uint8_t>(s.repair_percent, 100);
        ack.status = CalibrationStatus::kFailed;
        return ack;
      case kRepairing:
        ack.progress_percent = std::min<uint8_t>(s.repair_percent, 99);
        ack.status = CalibrationStatus::kInProgress;
        return ack;
      default:  // a firmware upgrade: says nothing about the calibration
        break;
    }
  }
  const double waited_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - run->accepted).count();
  // No report for too long: the bridge cannot tell (0x01), and says so rather than guess.
  if (waited_s > options_.calibration_report_timeout_s)
    return refused<CalibrationProgressAck>(AckCode::kError);
  ack.progress_percent = 0;
  ack.status = CalibrationStatus::kInProgress;
  return ack;
}

void SkyportBridge::register_gimbal() {
  // The pod's yaw is a joint angle relative to the aircraft: it follows the aircraft's heading,
  // PSDK's "following" mode, the only one it has.
  session_.handle<GetGimbalCapability>([](const GetGimbalCapability&) {
    GimbalCapabilityAck ack;
    ack.supported = true;
    return ack;
  });
  session_.handle<GetGimbalState>([this](const GetGimbalState&) {
    const PodSnapshot s = pod_.snapshot();
    const bool ned = options_.gimbal_angle_layout == PsdkLayout::kDjiHeaders;
    if (ned ? !s.have_attitude : !s.have_joints) return refused<GimbalStateAck>(AckCode::kError);
    GimbalStateAck ack;
    // "Following" in the numbering `gimbal_mode_layout` picks (P28).
    ack.mode = static_cast<GimbalStateMode>(
        gimbal_state_mode_code(GimbalMode::kFollowing, options_.gimbal_mode_layout));
    // NED (P28): the attitude angles; the pod's attitude yaw is north-referenced once it is fed
    // the aircraft's attitude. Else the joint angles.
    const double pitch = ned ? s.attitude_pitch_rad : s.pitch_rad;
    const double roll = ned ? s.attitude_roll_rad : s.roll_rad;
    const double yaw = ned ? s.attitude_yaw_rad : s.yaw_rad;
    ack.angles.pitch_deg = -pitch * kDegPerRad;
    ack.angles.yaw_deg = -yaw * kDegPerRad;
    ack.angles.roll_deg = roll * kDegPerRad;
    return ack;
  });
  session_.handle<SetGimbalMode>([this](const SetGimbalMode& c) {
    return c.mode == GimbalMode::kFollowing ? AckCode::kOk : unsupported();
  });
  deferred<GimbalReturnHead>(
      [this](const GimbalReturnHead&) { return pod_code(pod_.center(), "return head"); });
  deferred<ControlGimbalSpeed>([this](const ControlGimbalSpeed& c) {
    // The range (+-180 deg/s, 3.5.4) is checked by deferred(); the roll here.
    if (c.action == GimbalControlAction::kStop) return pod_code(pod_.set_rate(0, 0), "speed");
    if (std::fabs(c.roll_rate_deg_s) > kRollDeadbandDeg)
      return invalid("gimbal speed: roll rate " + std::to_string(c.roll_rate_deg_s) +
                     " deg/s, but the pod's roll only stabilises");
    return pod_code(pod_.set_rate(-c.pitch_rate_deg_s / kDegPerRad, -c.yaw_rate_deg_s / kDegPerRad),
                    "gimbal speed");
  });
  const auto angle = [this](double pitch_deg, double roll_deg, double yaw_deg) {
    if (std::fabs(roll_deg) > kRollDeadbandDeg)
      return invalid("gimbal angle: roll " + std::to_string(roll_deg) +
                     " deg, but the pod's roll only stabilises");
    return pod_code(pod_.set_angle(-pitch_deg / kDegPerRad, -yaw_deg / kDegPerRad), "angle");
  };
  // 3.5.5 names angles in the state's frame (P28): NED with `dji_headers`, converted to the
  // joint target with the pod's offset now; joint angles with `document`.
  deferred<ControlGimbalAngle>([this, angle](const ControlGimbalAngle& c) {
    if (options_.gimbal_angle_layout != PsdkLayout::kDjiHeaders)
      return angle(c.pitch_deg, c.roll_deg, c.yaw_deg);
    const std::optional<GimbalTargetDeg> joint =
        joint_target_from_ned({c.pitch_deg, c.yaw_deg}, pod_.snapshot());
    if (!joint)
      return invalid(
          "gimbal angle: NED angles (gimbal_angle_layout dji_headers) need the pod's attitude "
          "and joint angles, and the pod has not reported both yet");
    return angle(joint->pitch_deg, c.roll_deg, joint->yaw_deg);
  });
  // 3.5.6: joint angles in either layout. Return head: the joints' centre in either layout.
  deferred<ControlGimbalJointAngle>([angle](const ControlGimbalJointAngle& c) {
    return angle(c.angles.pitch_deg, c.angles.roll_deg, c.angles.yaw_deg);
  });
  deferred<CalibrateGimbal>([this](const CalibrateGimbal&) {
    const uint64_t reports_before = pod_.snapshot().repair_status_count;
    const AckCode code = pod_code(pod_.calibrate(), "calibration");
    if (code == AckCode::kOk) {
      std::lock_guard<std::mutex> lock(mutex_);
      calibration_ = Calibration{std::chrono::steady_clock::now(), reports_before};
    }
    return code;
  });
  session_.handle<GetCalibrationProgress>(
      [this](const GetCalibrationProgress&) { return calibration_progress(pod_.snapshot()); });
  from_snapshot<GetGimbalAdditionalStatus>(&PodSnapshot::have_joints, [](const PodSnapshot& s) {
    GimbalAdditionalStatusAck ack;
    ack.pitch_rate_deg_s = -s.pitch_rate_rad_s * kDegPerRad;
    ack.yaw_rate_deg_s = -s.yaw_rate_rad_s * kDegPerRad;
    ack.roll_rate_deg_s = s.roll_rate_rad_s * kDegPerRad;
    return ack;
  });
}

}  // namespace k40t::driver::skyport
