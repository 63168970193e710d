#include "k40t_driver/sim/attitude_order.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace k40t::sim {

namespace {

using Matrix = std::array<std::array<double, 3>, 3>;

Matrix operator*(const Matrix& a, const Matrix& b) {
  Matrix out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) out[i][j] += a[i][k] * b[k][j];
  return out;
}

// Right-handed rotations about x forward, y left, z up (REP 103), by `a` radians.
Matrix about_x(double a) {
  return {{{1, 0, 0}, {0, std::cos(a), -std::sin(a)}, {0, std::sin(a), std::cos(a)}}};
}
Matrix about_y(double a) {
  return {{{std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}}};
}
Matrix about_z(double a) {
  return {{{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}}};
}

}  // namespace

YawPitchRoll attitude_in_order(const YawPitchRoll& chain_deg, protocol::AttitudeOrder order) {
  if (order == protocol::AttitudeOrder::kZxy) return chain_deg;
  // In REP 103 terms a right yaw and an up pitch are negative rotations; right-down roll positive.
  const Matrix r = about_z(-deg_to_rad(chain_deg.yaw)) * about_x(deg_to_rad(chain_deg.roll)) *
                   about_y(-deg_to_rad(chain_deg.pitch));
  // r = Rz(yaw') Ry(pitch') Rx(roll'): the Z-Y-X angles of the same rotation.
  const double yaw = std::atan2(r[1][0], r[0][0]);
  const double pitch = std::asin(std::clamp(-r[2][0], -1.0, 1.0));
  const double roll = std::atan2(r[2][1], r[2][2]);
  return {-rad_to_deg(yaw), -rad_to_deg(pitch), rad_to_deg(roll)};
}

}  // namespace k40t::sim
