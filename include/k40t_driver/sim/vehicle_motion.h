// How the simulated vehicle moves over the ground (the truth frame of ground_truth.h: metres
// north and east of the take-off point): a constant velocity (hover at zero) or a circle at a
// constant speed, each from a model time on, starting where the vehicle is then, so the control
// socket can change it mid-run (`fly`, `orbit`) without a jump.
#pragma once

#include "k40t_driver/sim/geometry.h"

namespace k40t::sim {

class VehicleMotion {
 public:
  // From model time 0 at the take-off point, at this constant velocity.
  VehicleMotion(double velocity_north_m_s, double velocity_east_m_s);

  // From `now_s` on: a constant velocity.
  void fly(double now_s, double velocity_north_m_s, double velocity_east_m_s);
  // From `now_s` on: a circle about (centre_north_m, centre_east_m) through where the vehicle is
  // then, at `speed_m_s` (positive clockwise seen from above, negative counter-clockwise).
  // Fails (and changes nothing) when the vehicle is at the centre.
  bool orbit(double now_s, double centre_north_m, double centre_east_m, double speed_m_s);

  // x north, y east (metres; z is 0: the height is the world's).
  Vec3 position(double t_s) const;
  Vec3 velocity(double t_s) const;

 private:
  double start_s_ = 0;
  double start_north_ = 0;
  double start_east_ = 0;
  double velocity_north_ = 0;
  double velocity_east_ = 0;
  bool orbiting_ = false;
  double centre_north_ = 0;
  double centre_east_ = 0;
  double radius_ = 0;
  double start_angle_ = 0;    // rad, of the start position about the centre, from north to east
  double angular_speed_ = 0;  // rad/s, positive clockwise (north towards east)
};

}  // namespace k40t::sim
