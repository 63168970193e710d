// RateCommander: rate commands -> direction + dial speed, sent on change only, and the dead-man.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/driver/rate_commander.h"

namespace k40t::driver {
namespace {

using protocol::GimbalPitchDirection;
using protocol::GimbalYawDirection;
using Clock = RateCommander::Clock;
using std::chrono::milliseconds;

class RateCommanderTest : public ::testing::Test {
 protected:
  RateCommander rate{milliseconds(500)};
  Clock::time_point t0 = Clock::now();
};

TEST_F(RateCommanderTest, FirstCommandSendsSpeedThenDirections) {
  const RateCommander::Output out = rate.command(10.0, -4.0, t0);
  ASSERT_TRUE(out.speed.has_value());
  EXPECT_DOUBLE_EQ(out.speed->pitch_speed_deg_s, 10.0);
  EXPECT_DOUBLE_EQ(out.speed->yaw_speed_deg_s, 4.0);
  ASSERT_TRUE(out.control.has_value());
  EXPECT_EQ(out.control->pitch, GimbalPitchDirection::kUp);  // pod convention: up positive
  EXPECT_EQ(out.control->yaw, GimbalYawDirection::kLeft);    // right positive, so -4 is left
  EXPECT_EQ(out.control->mode, protocol::GimbalMode::kNone);
  EXPECT_FALSE(out.deadman_stop);
  EXPECT_TRUE(rate.moving());
}

TEST_F(RateCommanderTest, RepeatedCommandSendsNothing) {
  rate.command(10.0, 5.0, t0);
  EXPECT_TRUE(rate.command(10.0, 5.0, t0 + milliseconds(100)).empty());
  // A change below the dial's 0.2 deg/s resolution is no change either.
  EXPECT_TRUE(rate.command(10.05, 5.0, t0 + milliseconds(200)).empty());
}

TEST_F(RateCommanderTest, SpeedSetElsewhereIsSentAgain) {
  rate.command(10.0, 5.0, t0);
  protocol::GimbalDialSpeedRequest own;
  own.pitch_speed_deg_s = 10.0;
  own.yaw_speed_deg_s = 5.0;
  rate.speed_sent(own);  // its own frame going out: still the pod's speed
  EXPECT_TRUE(rate.command(10.0, 5.0, t0 + milliseconds(100)).empty());
  protocol::GimbalDialSpeedRequest reconfigure;
  reconfigure.pitch_speed_deg_s = 30.0;
  reconfigure.yaw_speed_deg_s = 30.0;
  rate.speed_sent(reconfigure);
  RateCommander::Output out = rate.command(10.0, 5.0, t0 + milliseconds(200));
  ASSERT_TRUE(out.speed.has_value());
  EXPECT_DOUBLE_EQ(out.speed->pitch_speed_deg_s, 10.0);
  EXPECT_DOUBLE_EQ(out.speed->yaw_speed_deg_s, 5.0);
  EXPECT_FALSE(out.control.has_value());
  rate.forget_speed();  // reconnect, restart, refusal
  EXPECT_TRUE(rate.command(10.0, 5.0, t0 + milliseconds(300)).speed.has_value());
}

TEST_F(RateCommanderTest, SpeedChangeKeepsDirections) {
  rate.command(10.0, 5.0, t0);
  const RateCommander::Output out = rate.command(20.0, 5.0, t0 + milliseconds(100));
  ASSERT_TRUE(out.speed.has_value());
  EXPECT_DOUBLE_EQ(out.speed->pitch_speed_deg_s, 20.0);
  EXPECT_DOUBLE_EQ(out.speed->yaw_speed_deg_s, 5.0);
  EXPECT_FALSE(out.control.has_value());
}

TEST_F(RateCommanderTest, ZeroRatesStopAtOnceWithoutSpeed) {
  rate.command(10.0, 5.0, t0);
  const RateCommander::Output out = rate.command(0.0, 0.0, t0 + milliseconds(100));
  EXPECT_FALSE(out.speed.has_value());
  ASSERT_TRUE(out.control.has_value());
  EXPECT_EQ(out.control->pitch, GimbalPitchDirection::kStop);
  EXPECT_EQ(out.control->yaw, GimbalYawDirection::kStop);
  EXPECT_FALSE(rate.moving());
  EXPECT_FALSE(rate.deadline().has_value());
}

TEST_F(RateCommanderTest, RatesAreClampedToTheDialRange) {
  RateCommander::Output out = rate.command(100.0, 0.5, t0);
  ASSERT_TRUE(out.speed.has_value());
  EXPECT_DOUBLE_EQ(out.speed->pitch_speed_deg_s, 30.0);  // the document's maximum
  EXPECT_DOUBLE_EQ(out.speed->yaw_speed_deg_s, 1.0);     // and minimum
  out = rate.command(0.1, -0.1, t0 + milliseconds(10));  // inside the dead band: stop
  ASSERT_TRUE(out.control.has_value());
  EXPECT_EQ(out.control->pitch, GimbalPitchDirection::kStop);
  EXPECT_EQ(out.control->yaw, GimbalYawDirection::kStop);
}

TEST_F(RateCommanderTest, NonFiniteRatesStopTheAxis) {
  const RateCommander::Output out = rate.command(std::nan(""), INFINITY, t0);
  EXPECT_FALSE(out.speed.has_value());
  EXPECT_FALSE(out.control.has_value());  // already stopped: nothing to send
  EXPECT_FALSE(rate.moving());
}

TEST_F(RateCommanderTest, DeadmanStopsAfterTheTimeout) {
  rate.command(-10.0, 0.0, t0);
  ASSERT_TRUE(rate.deadline().has_value());
  EXPECT_EQ(*rate.deadline(), t0 + milliseconds(500));
  EXPECT_TRUE(rate.tick(t0 + milliseconds(499)).empty());
  const RateCommander::Output out = rate.tick(t0 + milliseconds(500));
  EXPECT_TRUE(out.deadman_stop);
  ASSERT_TRUE(out.control.has_value());
  EXPECT_EQ(out.control->pitch, GimbalPitchDirection::kStop);
  EXPECT_EQ(out.control->yaw, GimbalYawDirection::kStop);
  EXPECT_FALSE(rate.moving());
  EXPECT_TRUE(rate.tick(t0 + milliseconds(900)).empty());  // stops once
}

TEST_F(RateCommanderTest, EachCommandMovesTheDeadline) {
  rate.command(-10.0, 0.0, t0);
  rate.command(-10.0, 0.0, t0 + milliseconds(400));
  EXPECT_TRUE(rate.tick(t0 + milliseconds(600)).empty());
  EXPECT_TRUE(rate.tick(t0 + milliseconds(900)).deadman_stop);
}

TEST_F(RateCommanderTest, CommandAfterDeadmanResendsDirections) {
  rate.command(-10.0, 0.0, t0);
  rate.tick(t0 + milliseconds(600));
  const RateCommander::Output out = rate.command(-10.0, 0.0, t0 + milliseconds(700));
  EXPECT_FALSE(out.speed.has_value());  // the dial speed did not change
  ASSERT_TRUE(out.control.has_value());
  EXPECT_EQ(out.control->pitch, GimbalPitchDirection::kDown);
}

}  // namespace
}  // namespace k40t::driver
