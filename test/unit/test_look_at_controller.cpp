// driver/look_at_controller.h: the control step of gimbal/look_at, alone (hand-worked figures)
// and closed around the simulated pod's gimbal (sim/gimbal_model.h) with the link's delays, for
// both drives: the figures docs/geo.md and docs/ros_interface.md quote for the choice of the
// angle drive come from ClosedLoop.* (printed).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <vector>

#include "k40t_driver/driver/look_at_controller.h"
#include "k40t_driver/driver/rate_commander.h"
#include "k40t_driver/sim/gimbal_model.h"

namespace k40t::driver {
namespace {

using geo::GimbalAim;
using geo::Vector3;

TEST(LookAtController, HoldsAStillTargetWithOneCommand) {
  LookAtController controller({});
  // 100 m ahead, 100 m right, level: yaw 45 right.
  const LookAtStep first = controller.step(0.0, {100, -100, 0}, std::nullopt);
  ASSERT_TRUE(first.reach);
  ASSERT_TRUE(first.angle);
  EXPECT_NEAR(first.angle->yaw_deg, 45, 1e-9);
  EXPECT_NEAR(first.angle->pitch_deg, 0, 1e-9);
  EXPECT_TRUE(std::isnan(first.error_deg));  // no joint report yet
  const LookAtStep second = controller.step(0.05, {100, -100, 0}, GimbalAim{45, 0});
  EXPECT_FALSE(second.angle);  // nothing changed: nothing sent
  EXPECT_NEAR(second.error_deg, 0, 1e-9);
}

Vector3 at_yaw(double yaw_deg) {
  const double y = yaw_deg * M_PI / 180;
  return Vector3{std::cos(y), -std::sin(y), 0};
}

TEST(LookAtController, LeadsAMovingTarget) {
  LookAtConfig config;
  config.lead_s = 0.1;
  LookAtController controller(config);
  // The target turns right at 10 deg/s; steps every 0.05 s. Before 0.2 s (the rate window) no
  // rate is known: the command is the target itself.
  const LookAtStep first = controller.step(0.0, at_yaw(0), std::nullopt);
  EXPECT_NEAR(first.angle->yaw_deg, 0, 1e-9);
  for (int i = 1; i <= 3; ++i) controller.step(0.05 * i, at_yaw(0.5 * i), std::nullopt);
  EXPECT_NEAR(controller.rate_estimate().yaw_deg, 0, 1e-9);
  const LookAtStep step = controller.step(0.2, at_yaw(2.0), std::nullopt);
  EXPECT_NEAR(controller.rate_estimate().yaw_deg, 10, 1e-9);
  ASSERT_TRUE(step.angle);
  EXPECT_NEAR(step.angle->yaw_deg, 2.0 + 10 * 0.1, 1e-9);  // where it will be 0.1 s later
  // What the target was computed from is 0.05 s old: led by that much more.
  const LookAtStep late = controller.step(0.3, at_yaw(2.5), std::nullopt, 0, 0.05);
  EXPECT_NEAR(late.angle->yaw_deg, 2.5 + 10 * 0.15, 1e-9);
}

TEST(LookAtController, RateOfATargetSlowerThanTheSteps) {
  // A 10 Hz tracker's points at 20 Hz steps: every other step sees the same point. The rate is
  // the change over the window, not over one step (which would give 0 and 20 deg/s in turn).
  LookAtController controller({});
  for (int i = 0; i <= 12; ++i) {
    const double t = 0.05 * i;
    const double point_t = 0.1 * (i / 2);
    controller.step(t, at_yaw(10 * point_t), std::nullopt);
    if (t >= 0.3) {
      EXPECT_NEAR(controller.rate_estimate().yaw_deg, 10, 2.6) << t;
    }
  }
}

TEST(LookAtController, RefusesATargetAboveTheUpperLimit) {
  LookAtController controller({});
  // 100 m ahead, 100 m up: 45 deg up, above the pod's 30.
  const LookAtStep step = controller.step(0, {100, 0, 100}, std::nullopt);
  EXPECT_FALSE(step.reach);
  EXPECT_NE(step.reach.message().find("above the gimbal's upper limit"), std::string::npos);
  EXPECT_FALSE(step.angle);
  EXPECT_FALSE(step.rate);
  EXPECT_FALSE(controller.step(0, {0, 0, 0}, std::nullopt).reach);
}

TEST(LookAtController, RateDriveTurnsTheShortWayWhenContinuous) {
  LookAtConfig config;
  config.drive = LookAtDrive::kRate;
  config.limits.yaw_continuous = true;
  config.rate_gain = 2;
  LookAtController controller(config);
  // Target at yaw -170 (170 left), gimbal at +170: 20 deg to the right through the back.
  const double y = -170 * M_PI / 180;
  const LookAtStep step = controller.step(0, {std::cos(y), -std::sin(y), 0}, GimbalAim{170, 0});
  ASSERT_TRUE(step.rate);
  EXPECT_NEAR(step.rate->yaw_deg, 30, 1e-9);  // 2/s x 20 deg = 40 deg/s, capped at 30
  config.limits.yaw_continuous = false;
  LookAtController stops(config);
  const LookAtStep back = stops.step(0, {std::cos(y), -std::sin(y), 0}, GimbalAim{170, 0});
  EXPECT_NEAR(back.rate->yaw_deg, -30, 1e-9);  // end stops: 340 deg left, through 0
  // Close to the target: feed-forward (none yet) plus gain x error, 2 x 0.25 = 0.5 deg/s.
  LookAtController fresh(config);
  const LookAtStep near = fresh.step(0, {1, 0, 0}, GimbalAim{-0.25, 0});
  EXPECT_NEAR(near.rate->yaw_deg, 0.5, 1e-9);
}

TEST(FootprintZoom, KeepsTheWidthAndIgnoresSmallChanges) {
  FootprintZoom zoom(30, 2.8 / 4.7);
  // 152.97 m: 6.075x, asked as 6.1 (0.1 steps).
  const std::optional<double> first = zoom.step(std::hypot(150.0, 30.0));
  ASSERT_TRUE(first);
  EXPECT_NEAR(*first, 6.1, 1e-9);
  EXPECT_FALSE(zoom.step(155));                          // 6.2x: within 3 % of 6.1
  const std::optional<double> further = zoom.step(200);  // 7.94 -> 7.9
  ASSERT_TRUE(further);
  EXPECT_NEAR(*further, 7.9, 1e-9);
  EXPECT_FALSE(zoom.step(0));
}

// The closed loop: the simulated gimbal stepped every 5 ms; the controller every 50 ms (20 Hz)
// with the joint report of 0x000002 (10 Hz, 10 ms old); its commands reach the gimbal 20 ms later
// (the request's way to the pod).
struct Loop {
  LookAtConfig config;
  std::function<Vector3(double)> target;  // in the base frame at time t
  double seconds = 10;
  double settle_s = 0;       // errors before this are not counted
  double start_off_deg = 0;  // the gimbal starts this far right of the target

  std::vector<double> run() {
    sim::GimbalConfig gimbal_config;
    gimbal_config.yaw_continuous = config.limits.yaw_continuous;
    sim::GimbalModel gimbal(gimbal_config);
    sim::EventQueue events;
    LookAtController controller(config);
    RateCommander rates;
    gimbal.set_dial_speed(config.max_rate_deg_s, config.max_rate_deg_s);  // the glue's 0x000017
    // Start on the target, as after a first settle.
    const GimbalAim start = geo::aim_along(target(0)).value();
    gimbal.command_angles(start.pitch_deg, start.yaw_deg + start_off_deg);
    for (int i = 0; i < 2000; ++i) gimbal.step(0.005, events);

    std::deque<std::pair<double, std::function<void()>>> in_flight;
    std::optional<GimbalAim> report;
    double report_s = 0;
    GimbalAim sampled;
    std::vector<double> errors;
    const double dt = 0.005;
    for (int i = 0; i * dt < seconds; ++i) {
      const double t = i * dt;
      while (!in_flight.empty() && in_flight.front().first <= t + 1e-9) {
        in_flight.front().second();
        in_flight.pop_front();
      }
      if (i % 20 == 0)
        sampled = GimbalAim{gimbal.pose().joint_deg.yaw, gimbal.pose().joint_deg.pitch};
      if (i % 20 == 2) {  // 10 Hz, arriving 10 ms after it was taken
        report = sampled;
        report_s = t - 0.01;
      }
      if (i % 10 == 0) {  // 20 Hz
        const LookAtStep step = controller.step(t, target(t), report, report_s);
        if (step.angle) {
          const GimbalAim a = *step.angle;
          in_flight.push_back(
              {t + 0.02, [&gimbal, a] { gimbal.command_angles(a.pitch_deg, a.yaw_deg); }});
        }
        if (step.rate) {
          const RateCommander::Output out = rates.command(step.rate->pitch_deg, step.rate->yaw_deg,
                                                          RateCommander::Clock::time_point{});
          in_flight.push_back({t + 0.02, [&gimbal, out] { apply(gimbal, out); }});
        }
      }
      gimbal.step(dt, events);
      if (t >= settle_s) {
        const GimbalAim now{gimbal.pose().joint_deg.yaw, gimbal.pose().joint_deg.pitch};
        errors.push_back(geo::pointing_error_deg(now, target(t + dt)));
      }
    }
    std::sort(errors.begin(), errors.end());
    return errors;
  }

  static void apply(sim::GimbalModel& gimbal, const RateCommander::Output& out) {
    if (out.speed) gimbal.set_dial_speed(out.speed->pitch_speed_deg_s, out.speed->yaw_speed_deg_s);
    if (!out.control) return;
    using protocol::GimbalPitchDirection;
    using protocol::GimbalYawDirection;
    const auto yaw = out.control->yaw == GimbalYawDirection::kLeft    ? sim::YawMotion::kLeft
                     : out.control->yaw == GimbalYawDirection::kRight ? sim::YawMotion::kRight
                                                                      : sim::YawMotion::kStop;
    const auto pitch = out.control->pitch == GimbalPitchDirection::kUp ? sim::PitchMotion::kUp
                       : out.control->pitch == GimbalPitchDirection::kDown
                           ? sim::PitchMotion::kDown
                           : sim::PitchMotion::kStop;
    gimbal.move(yaw, pitch);
  }
};

double percentile(const std::vector<double>& sorted, double p) {
  return sorted[static_cast<size_t>(p * (sorted.size() - 1))];
}

// The straight pass of the rostest: 15 m/s north, the target 100 m east of the track and 30 m
// below, from 75 m before abeam to 75 m after (peak yaw rate 15/100 rad/s = 8.6 deg/s).
Vector3 straight_pass(double t) {
  const double north = 15 * t - 75;
  return {-north, -100, -30};  // heading north: x = north, y = -east (left), z = up
}

// A still target at 100 m slant, 30 m below.
Vector3 hover(double) {
  return {std::sqrt(100.0 * 100.0 - 30.0 * 30.0), 0, -30};
}

void print(const char* what, const std::vector<double>& errors) {
  std::printf("[ figures  ] %s: pointing error p50 %.3f p95 %.3f max %.3f deg\n", what,
              percentile(errors, 0.5), percentile(errors, 0.95), errors.back());
}

TEST(ClosedLoop, AngleDriveFollowsTheStraightPass) {
  Loop loop;
  loop.target = straight_pass;
  const std::vector<double> errors = loop.run();
  print("angle drive, straight pass 15 m/s 100 m abeam", errors);
  EXPECT_LE(percentile(errors, 0.95), 1.0);  // the target
}

TEST(ClosedLoop, RateDriveFollowsTheStraightPass) {
  Loop loop;
  loop.config.drive = LookAtDrive::kRate;
  loop.target = straight_pass;
  const std::vector<double> errors = loop.run();
  print("rate drive, straight pass 15 m/s 100 m abeam", errors);
  EXPECT_LE(percentile(errors, 0.95), 1.0);
}

TEST(ClosedLoop, AngleDriveHoldsAStillTargetExactly) {
  Loop loop;
  loop.target = hover;
  loop.start_off_deg = 5;
  loop.settle_s = 3;
  const std::vector<double> errors = loop.run();
  print("angle drive, hover 100 m", errors);
  EXPECT_LE(errors.back(), 0.01);  // 0x000012's resolution
}

TEST(ClosedLoop, RateDriveStopsShortOfAStillTarget) {
  // The pod turns no slower than 1 deg/s and RateCommander stops an axis below 0.2 deg/s: the
  // rate drive comes in at 1 deg/s and stops where gain x error falls below 0.2 deg/s, short of
  // the target (0.029 deg here). Measured, not a target.
  Loop loop;
  loop.config.drive = LookAtDrive::kRate;
  loop.target = hover;
  loop.start_off_deg = 5;
  loop.settle_s = 3;
  const std::vector<double> errors = loop.run();
  print("rate drive, hover 100 m", errors);
  EXPECT_GT(errors.back(), 0.01);  // worse than the angle drive: why the angle drive is the default
}

}  // namespace
}  // namespace k40t::driver
