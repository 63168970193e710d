// Turns gimbal rate commands into what the protocol offers, and stops the gimbal when they stop
// coming (the dead-man of gimbal/cmd_rate).
//
// The pod has no rate command: 0x000010 starts or stops turning per axis (left/right/stop,
// up/down/stop) and 0x000017 sets the speed it turns at (the "dial speed", 1..30 deg/s in steps of
// 0.2 deg/s). So a rate becomes a direction per axis plus a dial speed, each sent only when it
// changes, and with no command for `timeout` both axes are told to stop. Pure logic, no I/O: the
// driver sends what the Output asks for, and tells it what else changed the pod's dial speed
// (speed_sent, forget_speed), so that "only when it changes" compares with what the pod has.
#pragma once

#include <chrono>
#include <optional>

#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::driver {

class RateCommander {
 public:
  using Clock = std::chrono::steady_clock;

  struct Output {
    std::optional<protocol::GimbalDialSpeedRequest> speed;  // send first, if set
    std::optional<protocol::GimbalControlRequest> control;  // then this
    bool deadman_stop = false;                              // control is the dead-man's stop
    bool empty() const { return !speed && !control; }
  };

  // Rates below this (deg/s) mean "stop this axis": the slowest dial speed is 1 deg/s.
  static constexpr double kDeadbandDegS = 0.2;

  explicit RateCommander(std::chrono::duration<double> timeout = std::chrono::milliseconds(500));

  void set_timeout(std::chrono::duration<double> timeout) { timeout_ = timeout; }

  // Pod convention: pitch up positive, yaw right positive, deg/s. Non-finite rates stop the axis.
  Output command(double pitch_deg_s, double yaw_deg_s, Clock::time_point now);
  // Call at least at deadline(); returns the dead-man stop when it is due.
  Output tick(Clock::time_point now);
  // When tick() must next run, or nullopt while the gimbal is not being turned.
  std::optional<Clock::time_point> deadline() const;
  bool moving() const { return moving_; }

  // A 0x000017 went out (this commander's, or another's: dynamic_reconfigure, `send`): unless it
  // is the speed last sent from here, the pod no longer turns at that speed.
  void speed_sent(const protocol::GimbalDialSpeedRequest& sent);
  // The pod's dial speed is unknown (a reconnect, a gimbal restart, a 0x000017 refused or never
  // answered): the next command that moves an axis sends its speed again.
  void forget_speed();

 private:
  std::chrono::duration<double> timeout_;
  bool moving_ = false;
  protocol::GimbalPitchDirection pitch_direction_ = protocol::GimbalPitchDirection::kStop;
  protocol::GimbalYawDirection yaw_direction_ = protocol::GimbalYawDirection::kStop;
  int pitch_speed_wire_ = 0;  // last dial speed sent, in wire units (deg/s x5); 0 = never
  int yaw_speed_wire_ = 0;
  Clock::time_point last_command_{};
};

}  // namespace k40t::driver
