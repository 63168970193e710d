// The simulated gimbal (document section 3.1): joint angles that move toward what was commanded at
// the dial speed, inside the mechanical limits (pitch +30/-90, yaw +-180, by default no wrap
// through the back: the yaw joint has end stops; `yaw_continuous` (--gimbal-yaw-continuous)
// makes it turn through +-180 instead, the short way to a commanded angle), plus the servo,
// stabilisation, calibration and restart states the status report shows. Pure model: no wire
// format, no wall clock; step(dt) advances it.
//
// Motion is at constant speed (no acceleration phase), so a move of A degrees at dial speed S
// takes A / S seconds: what the document's "dial speed, corresponding to 1-30 degrees/second"
// promises.
#pragma once

#include <optional>

#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/sim/events.h"
#include "k40t_driver/sim/geometry.h"
#include "k40t_driver/sim/lens.h"
#include "k40t_driver/sim/outcome.h"

namespace k40t::sim {

enum class YawMotion { kLeft, kRight, kStop };
enum class PitchMotion { kUp, kDown, kStop };
// Byte 4 of 0x000001 (3.1.1.1).
enum class StabilisationState : uint8_t { kOff = 0, kActive = 1, kFailed = 2, kLost = 3 };
enum class CalibrationKind { kDrift, kLinear, kAccelerometer };

struct GimbalConfig {
  double pitch_min_deg = -90;
  double pitch_max_deg = 30;
  double yaw_min_deg = -180;
  double yaw_max_deg = 180;
  bool yaw_continuous =
      false;  // no end stops: +-180 is one place, angles are reached the short way
  double min_dial_speed_deg_s = 1;
  double max_dial_speed_deg_s = 30;
  double default_dial_speed_deg_s = protocol::GimbalDialSpeedRequest::kDefaultDegS;
  double drift_calibration_s = 5;
  double linear_calibration_s = 8;
  double accelerometer_calibration_s = 6;
  double restart_s = 2;  // soft restart: motors off, then back to centre
  // The roll joint's angle (right-down positive), held: the document has no roll command. Not 0,
  // it lets the attitude report show its Euler order (attitude_order); the world geometry
  // (laser, video, pointing) keeps a camera without roll.
  double roll_deg = 0;
};

// What 0x000002 reports. Joint angles are relative to the pod's base (the chain yaw, roll, pitch);
// the vehicle is level, so the attitude is the joints' rotation turned by the vehicle heading.
struct GimbalPose {
  YawPitchRoll joint_deg;
  YawPitchRoll rate_deg_s;
};

class GimbalModel {
 public:
  explicit GimbalModel(const GimbalConfig& config = {});

  // 0x000017: maximum speeds, 1..30 deg/s.
  Outcome set_dial_speed(double pitch_deg_s, double yaw_deg_s);
  // 0x000012: absolute joint angles; an absent axis keeps its current motion.
  Outcome command_angles(std::optional<double> pitch_deg, std::optional<double> yaw_deg);
  // 0x000010: move in a direction at dial speed until stopped or at a limit.
  Outcome move(YawMotion yaw, PitchMotion pitch);
  Outcome centre();     // yaw 0, pitch 0
  Outcome look_down();  // yaw 0, pitch -90
  // 0x00002C: turn so that pixel (x, y) of a 1920x1080 image taken with `lens` at hybrid `zoom`
  // comes to the image centre.
  Outcome point_at(Lens lens, double zoom, double x_px, double y_px);
  // 0x000324 box tracking: turns to the box centre (as point_at) and holds it; manual motion is
  // refused (kBusy) until tracking stops ("send the off command to return to normal mode").
  Outcome start_tracking(Lens lens, double zoom, double x_px, double y_px);
  void stop_tracking() { tracking_ = false; }
  bool tracking() const { return tracking_; }
  Outcome servo_off();                 // 0x00002D: motors off; any motion command turns them on
  Outcome set_stabilisation(bool on);  // 0x000033
  Outcome start_calibration(CalibrationKind kind);  // 0x000013, 0x00002E, 0x000031
  Outcome soft_restart();                           // 0x00002F
  void set_use_flight_controller_attitude(bool use) { use_fc_attitude_ = use; }  // 0x000030

  // Calibrations report their progress as repairs (0x000008) into `events`, once a second.
  void step(double dt_s, EventQueue& events);

  GimbalPose pose() const { return pose_; }
  double yaw_target_deg() const { return yaw_.target; }
  double pitch_target_deg() const { return pitch_.target; }
  double pitch_dial_speed_deg_s() const { return pitch_.speed; }
  double yaw_dial_speed_deg_s() const { return yaw_.speed; }
  bool servo_on() const { return servo_on_; }
  bool stabilisation_enabled() const { return stabilisation_enabled_; }
  StabilisationState stabilisation_state() const;
  bool restarting() const { return restart_left_s_ > 0; }
  bool calibrating() const { return calibration_.has_value(); }
  std::optional<double> calibration_progress() const;  // 0..1
  bool use_flight_controller_attitude() const { return use_fc_attitude_; }
  const GimbalConfig& config() const { return config_; }

 private:
  enum class Drive { kHold, kToTarget, kNegative, kPositive };
  struct Axis {
    double angle = 0;
    double target = 0;
    double speed = 0;
    double min = 0;
    double max = 0;
    Drive drive = Drive::kHold;
    bool wraps = false;           // a continuous joint: angles in (-180, 180], no end stops
    void aim(double where);       // clamps to the limits
    double advance(double dt_s);  // returns the rate
  };
  struct Calibration {
    double duration_s = 0;
    double elapsed_s = 0;
    double next_report_s = 0;
  };

  Outcome ready_to_move();  // refuses while calibrating/restarting/tracking; turns the servo on
  Outcome aim_at_pixel(Lens lens, double zoom, double x_px, double y_px);
  static void set_motion(Axis& axis, bool negative, bool positive);

  GimbalConfig config_;
  Axis yaw_;
  Axis pitch_;
  GimbalPose pose_;
  bool servo_on_ = true;
  bool stabilisation_enabled_ = true;
  bool use_fc_attitude_ = false;
  bool tracking_ = false;
  double restart_left_s_ = 0;
  std::optional<Calibration> calibration_;
};

}  // namespace k40t::sim
