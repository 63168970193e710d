// The control step of gimbal/look_at and gimbal/look_at_point, ROS-free (docs/ros_interface.md
// "Looking at a place"): given where the target is in the gimbal's base frame now and the
// joint angles the pod last reported, what to send the pod, and how far off the boresight is.
//
// Two ways to drive the gimbal, both measured against the simulated pod (docs/geo.md):
//   kAngle  0x000012 with the angles the target will have `lead_s` later (its angular rate
//           estimated from the last steps), at most `max_rate_deg_s` (0x000017, sent once by the
//           glue): the pod goes there at its dial speed and holds. The default: it holds a
//           still target exactly and follows a moving one to a fraction of a degree.
//   kRate   0x000010 + 0x000017 through RateCommander: the target's angular rate plus
//           `rate_gain` x the error (the joint report moved on to now by the rate commanded). The
//           pod's slowest dial speed is 1 deg/s (0.2 deg/s steps), so a still or slow target is
//           held by switching between 1 deg/s and stop.
// Yaw takes the short way through +-180 when the yaw is continuous (limits.yaw_continuous);
// with end stops it stays inside them. A target above the upper pitch limit (or outside the
// reach otherwise) is refused with the reason, and the glue stops following.
#pragma once

#include <deque>
#include <optional>

#include "k40t_driver/geo/look_at_geometry.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::driver {

enum class LookAtDrive { kAngle, kRate };

struct LookAtConfig {
  geo::GimbalLimits limits;
  LookAtDrive drive = LookAtDrive::kAngle;
  double max_rate_deg_s = 30;  // the pod's fastest dial speed
  // Angle drive: how far ahead the command is aimed, s. Half a control step (the target moves
  // on while the gimbal holds the last command) plus the link's latency.
  double lead_s = 0.06;
  double rate_gain = 2.0;        // rate drive: 1/s
  double min_change_deg = 0.01;  // 0x000012's resolution: smaller changes are not sent
  // The target's angular rate is its change over at least this long (s): steps and targets
  // come at their own rates (a 10 Hz tracker, 20 Hz steps), and a difference over one step
  // would see 0 or twice the rate.
  double rate_window_s = 0.2;
};

struct LookAtStep {
  Status reach = Status::ok();          // not ok: the target is out of the gimbal's reach
  geo::GimbalAim desired;               // where the target is now
  std::optional<geo::GimbalAim> angle;  // send 0x000012 with these angles
  std::optional<geo::GimbalAim> rate;   // command these rates, deg/s (pod signs)
  double error_deg = 0;  // boresight (reported joints) to the target now; NaN unknown
};

class LookAtController {
 public:
  explicit LookAtController(const LookAtConfig& config) : config_(config) {}

  // One control step at `now_s` (seconds of the clock the reports are stamped with): `target` in
  // the gimbal's base frame, `joints` the last reported joint angles (none before the first
  // report), taken at `joints_s`.
  // `target_age_s`: how old what `target` was computed from is (the last fix, the TF's stamp):
  // the target is led by that much more.
  LookAtStep step(double now_s, const geo::Vector3& target,
                  const std::optional<geo::GimbalAim>& joints, double joints_s = 0,
                  double target_age_s = 0);
  // Forget the history (a new goal, a jump of the target).
  void reset();
  // The last angle command did not go out: the next step sends again even if nothing changed.
  void forget_sent() { sent_.reset(); }
  const LookAtConfig& config() const { return config_; }
  // The target's angular rate the controller estimates, deg/s.
  geo::GimbalAim rate_estimate() const { return rate_; }

 private:
  std::optional<geo::GimbalAim> angle_command(const geo::GimbalAim& predicted);
  // The joints now: the report moved on by the rate last commanded since it was taken (a report
  // is up to 0.1 s old; at 8.6 deg/s the gimbal has turned 0.9 deg since).
  geo::GimbalAim rate_command(const geo::GimbalAim& predicted, const geo::GimbalAim& joints_now);
  void update_rate(double now_s, const geo::GimbalAim& desired);

  LookAtConfig config_;
  struct Sample {
    double t_s;
    geo::GimbalAim aim;
  };
  std::deque<Sample> history_;  // the last targets, the oldest up to kMaxRateGapS back
  geo::GimbalAim rate_;
  std::optional<geo::GimbalAim> sent_;
  geo::GimbalAim commanded_rate_;
};

// The zoom policy "keep the footprint": the hybrid zoom ratio (0x000304, 0.1 steps) that keeps
// `width_m` across the image at the target's slant range, asked for again only when it differs
// from the last ratio asked by more than `hysteresis` (a zoom takes time; chasing every metre of
// range would keep the lens moving).
class FootprintZoom {
 public:
  FootprintZoom(double width_m, double tan_half_fov_1x, double hysteresis = 0.03)
      : width_m_(width_m), tan_half_fov_1x_(tan_half_fov_1x), hysteresis_(hysteresis) {}
  std::optional<double> step(double slant_m);

 private:
  double width_m_;
  double tan_half_fov_1x_;
  double hysteresis_;
  std::optional<double> asked_;
};

// The pod's hybrid zoom range (0x000304).
constexpr double kMinZoom = 1.0;
constexpr double kMaxZoom = 160.0;

}  // namespace k40t::driver
