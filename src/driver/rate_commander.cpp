#include "k40t_driver/driver/rate_commander.h"

#include <algorithm>
#include <cmath>

namespace k40t::driver {

using protocol::GimbalDialSpeedRequest;
using protocol::GimbalPitchDirection;
using protocol::GimbalYawDirection;

namespace {

// |rate| as dial-speed wire units, clamped to the document's 5..150; 0 for "stop".
int speed_wire(double rate_deg_s) {
  const double magnitude = std::fabs(rate_deg_s);
  if (!std::isfinite(magnitude) || magnitude < RateCommander::kDeadbandDegS) return 0;
  const double clamped =
      std::clamp(magnitude, GimbalDialSpeedRequest::kMinDegS, GimbalDialSpeedRequest::kMaxDegS);
  return static_cast<int>(std::lround(clamped * GimbalDialSpeedRequest::kWirePerDegS));
}

GimbalPitchDirection pitch_direction(int wire, double rate) {
  if (wire == 0) return GimbalPitchDirection::kStop;
  return rate > 0 ? GimbalPitchDirection::kUp : GimbalPitchDirection::kDown;
}

GimbalYawDirection yaw_direction(int wire, double rate) {
  if (wire == 0) return GimbalYawDirection::kStop;
  return rate > 0 ? GimbalYawDirection::kRight : GimbalYawDirection::kLeft;
}

}  // namespace

RateCommander::RateCommander(std::chrono::duration<double> timeout) : timeout_(timeout) {}

RateCommander::Output RateCommander::command(double pitch_deg_s, double yaw_deg_s,
                                             Clock::time_point now) {
  last_command_ = now;
  Output out;
  const int pitch_wire = speed_wire(pitch_deg_s);
  const int yaw_wire = speed_wire(yaw_deg_s);

  // A stopped axis keeps the speed last sent for it, so only the moving axes decide a resend.
  const int new_pitch_speed = pitch_wire != 0 ? pitch_wire : pitch_speed_wire_;
  const int new_yaw_speed = yaw_wire != 0 ? yaw_wire : yaw_speed_wire_;
  if ((pitch_wire != 0 || yaw_wire != 0) &&
      (new_pitch_speed != pitch_speed_wire_ || new_yaw_speed != yaw_speed_wire_)) {
    pitch_speed_wire_ = new_pitch_speed != 0 ? new_pitch_speed : new_yaw_speed;
    yaw_speed_wire_ = new_yaw_speed != 0 ? new_yaw_speed : new_pitch_speed;
    GimbalDialSpeedRequest speed;
    speed.pitch_speed_deg_s = pitch_speed_wire_ / GimbalDialSpeedRequest::kWirePerDegS;
    speed.yaw_speed_deg_s = yaw_speed_wire_ / GimbalDialSpeedRequest::kWirePerDegS;
    out.speed = speed;
  }

  const GimbalPitchDirection pitch = pitch_direction(pitch_wire, pitch_deg_s);
  const GimbalYawDirection yaw = yaw_direction(yaw_wire, yaw_deg_s);
  if (pitch != pitch_direction_ || yaw != yaw_direction_) {
    pitch_direction_ = pitch;
    yaw_direction_ = yaw;
    protocol::GimbalControlRequest control;
    control.pitch = pitch;
    control.yaw = yaw;
    out.control = control;
  }
  moving_ = pitch != GimbalPitchDirection::kStop || yaw != GimbalYawDirection::kStop;
  return out;
}

RateCommander::Output RateCommander::tick(Clock::time_point now) {
  Output out;
  const std::optional<Clock::time_point> due = deadline();
  if (!due || now < *due) return out;
  moving_ = false;
  pitch_direction_ = GimbalPitchDirection::kStop;
  yaw_direction_ = GimbalYawDirection::kStop;
  out.control = protocol::GimbalControlRequest{};  // mode none, both axes stop
  out.deadman_stop = true;
  return out;
}

void RateCommander::speed_sent(const GimbalDialSpeedRequest& sent) {
  const auto wire = [](double deg_s) {
    return static_cast<int>(std::lround(deg_s * GimbalDialSpeedRequest::kWirePerDegS));
  };
  if (wire(sent.pitch_speed_deg_s) != pitch_speed_wire_ ||
      wire(sent.yaw_speed_deg_s) != yaw_speed_wire_)
    forget_speed();
}

void RateCommander::forget_speed() {
  pitch_speed_wire_ = 0;
  yaw_speed_wire_ = 0;
}

std::optional<RateCommander::Clock::time_point> RateCommander::deadline() const {
  if (!moving_) return std::nullopt;
  return last_command_ + std::chrono::duration_cast<Clock::duration>(timeout_);
}

}  // namespace k40t::driver
