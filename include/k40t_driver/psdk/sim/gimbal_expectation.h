// What `check gimbal` expects 3.5.1 to read in the payload's frame (docs/psdk.md P28). Joint
// angles (the document's reading) stay where they were set. NED angles (DJI's headers) are the
// joints plus the aircraft's heading: a gimbal in "following" mode turns with the aircraft, and
// this adapter's aircraft circles. The payload learns the heading from the attitude pushes, late
// by 0 to `heading_lag_s` (the bridge feeds it to the pod once a second): the heading it knows
// at t is taken as the middle of the flight's headings over [t - lag, t], give or take half
// their span, at the command (when the payload converted the NED target to joints) and now.
#pragma once

#include <cmath>

#include "k40t_driver/psdk/sim/flight_model.h"

namespace k40t::psdk::sim {

struct ExpectedYaw {
  double yaw_deg = 0;        // DJI signs, [-180, 180)
  double tolerance_deg = 0;  // |reading - yaw_deg| allowed, after wrapping
  bool holds(double reading_deg) const {
    return std::abs(wrap_deg(reading_deg - yaw_deg)) <= tolerance_deg;
  }
  static double wrap_deg(double deg) {
    const double wrapped = std::fmod(deg + 180.0, 360.0);
    return (wrapped < 0 ? wrapped + 360.0 : wrapped) - 180.0;
  }
};

class GimbalExpectation {
 public:
  // `ned`: the payload answers in NED (PayloadReading::kDjiHeaders).
  GimbalExpectation(const FlightModel& flight, bool ned, double tolerance_deg,
                    double heading_lag_s = 2.0)
      : flight_(flight), ned_(ned), tolerance_deg_(tolerance_deg), lag_s_(heading_lag_s) {}

  // A yaw commanded by 3.5.5 at `command_s` (flight time), read at `now_s`: in NED, the joints
  // were aimed with the heading then and the reading adds the heading now.
  ExpectedYaw after_angle(double commanded_deg, double command_s, double now_s) const {
    if (!ned_) return {ExpectedYaw::wrap_deg(commanded_deg), tolerance_deg_};
    return {ExpectedYaw::wrap_deg(commanded_deg + known_heading_deg(now_s) -
                                  known_heading_deg(command_s)),
            tolerance_deg_ + doubt_deg(now_s) + doubt_deg(command_s)};
  }
  // After return head (joint yaw 0), read at `now_s`: in NED, the heading.
  ExpectedYaw centred(double now_s) const {
    if (!ned_) return {0.0, tolerance_deg_};
    return {ExpectedYaw::wrap_deg(known_heading_deg(now_s)), tolerance_deg_ + doubt_deg(now_s)};
  }

 private:
  double heading_deg(double t_s) const { return flight_.state_at(t_s).yaw_rad * 180.0 / M_PI; }
  // The flight's heading change over the lag before `t_s`, the way it turned.
  double lag_change_deg(double t_s) const {
    return ExpectedYaw::wrap_deg(heading_deg(t_s) - heading_deg(t_s - lag_s_));
  }
  // The heading the payload knows at `t_s`, and how far from it the true one it knows may be.
  double known_heading_deg(double t_s) const {
    return heading_deg(t_s - lag_s_) + lag_change_deg(t_s) / 2;
  }
  double doubt_deg(double t_s) const { return std::abs(lag_change_deg(t_s)) / 2; }
  const FlightModel& flight_;
  bool ned_;
  double tolerance_deg_;
  double lag_s_;
};

}  // namespace k40t::psdk::sim
