#include "k40t_driver/driver/laser_target_record.h"

#include <cstdlib>

namespace k40t::driver {

void LaserTargetRecord::range(double distance_m) {
  std::lock_guard<std::mutex> lock(mutex_);
  last_range_m_ = distance_m;
}

std::optional<double> LaserTargetRecord::last_range_m() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_range_m_;
}

void LaserTargetRecord::located(const geo::Geodetic& where, StampNs stamp) {
  std::lock_guard<std::mutex> lock(mutex_);
  summary_.last_error.clear();
  ++summary_.located;
  last_local_ = {where, stamp};
  compare_locked();
}

void LaserTargetRecord::not_located(const std::string& error) {
  std::lock_guard<std::mutex> lock(mutex_);
  summary_.last_error = error;
}

void LaserTargetRecord::pod_target(const protocol::TargetGpsAck& target, StampNs stamp) {
  if (target.code != protocol::ResponseCode::kOk) return;
  // The pod gives the altitude above mean sea level, the comparison is on the ellipsoid.
  const Result<double> h = geo::Geoid::egm96().ellipsoid_from_msl(
      target.latitude_deg, target.longitude_deg, target.altitude_m);
  if (!h) return;
  std::lock_guard<std::mutex> lock(mutex_);
  last_pod_ = {{target.latitude_deg, target.longitude_deg, h.value()}, stamp};
  compare_locked();
}

LaserTargetRecord::Summary LaserTargetRecord::summary() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return summary_;
}

void LaserTargetRecord::compare_locked() {
  if (!last_local_ || !last_pod_) return;
  if (std::llabs(last_local_->second - last_pod_->second) > kLaserTargetPairingNs) return;
  summary_.disagreement_m = geo::distance_m(last_local_->first, last_pod_->first);
}

}  // namespace k40t::driver
