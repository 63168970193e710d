#include "k40t_driver/sim/vehicle_motion.h"

#include <cmath>

namespace k40t::sim {

VehicleMotion::VehicleMotion(double velocity_north_m_s, double velocity_east_m_s)
    : velocity_north_(velocity_north_m_s), velocity_east_(velocity_east_m_s) {}

void VehicleMotion::fly(double now_s, double velocity_north_m_s, double velocity_east_m_s) {
  const Vec3 here = position(now_s);
  start_s_ = now_s;
  start_north_ = here.x;
  start_east_ = here.y;
  velocity_north_ = velocity_north_m_s;
  velocity_east_ = velocity_east_m_s;
  orbiting_ = false;
}

bool VehicleMotion::orbit(double now_s, double centre_north_m, double centre_east_m,
                          double speed_m_s) {
  const Vec3 here = position(now_s);
  const double radius = std::hypot(here.x - centre_north_m, here.y - centre_east_m);
  if (radius < 1e-6) return false;
  start_s_ = now_s;
  start_north_ = here.x;
  start_east_ = here.y;
  orbiting_ = true;
  centre_north_ = centre_north_m;
  centre_east_ = centre_east_m;
  radius_ = radius;
  start_angle_ = std::atan2(here.y - centre_east_m, here.x - centre_north_m);
  angular_speed_ = speed_m_s / radius;
  return true;
}

Vec3 VehicleMotion::position(double t_s) const {
  const double dt = t_s - start_s_;
  if (!orbiting_)
    return {start_north_ + velocity_north_ * dt, start_east_ + velocity_east_ * dt, 0};
  const double angle = start_angle_ + angular_speed_ * dt;
  return {centre_north_ + radius_ * std::cos(angle), centre_east_ + radius_ * std::sin(angle), 0};
}

Vec3 VehicleMotion::velocity(double t_s) const {
  if (!orbiting_) return {velocity_north_, velocity_east_, 0};
  const double angle = start_angle_ + angular_speed_ * (t_s - start_s_);
  const double speed = angular_speed_ * radius_;
  return {-speed * std::sin(angle), speed * std::cos(angle), 0};
}

}  // namespace k40t::sim
