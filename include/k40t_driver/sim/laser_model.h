// The laser rangefinder (section 3.2.5): a ray along the gimbal's boresight into the World. Over
// flat ground `h` metres below, at depression angle d, the range is h / sin(d); aimed at the hot
// object it is that object's distance; above the horizon (or beyond the maximum range) there is no
// return and the pod reports 0.
//
// It also answers the flight controller's target request (0x000320): where the laser spot is,
// from the host's own position, its heading, and the gimbal's aim.
#pragma once

#include <optional>

#include "k40t_driver/sim/geo_point.h"
#include "k40t_driver/sim/world.h"

namespace k40t::sim {

struct LaserConfig {
  double max_range_m = 3000;
};

class LaserModel {
 public:
  explicit LaserModel(const LaserConfig& config = {}) : config_(config) {}

  // Distance along heading `yaw_deg`, elevation `pitch_deg` (world frame), or none.
  std::optional<double> range(const World& world, double yaw_deg, double pitch_deg) const;

  // Where the laser hits, given the pod's own position (the host's fix): exact WGS 84 geodesy
  // (geo/geodesy.h), heights above sea level through the EGM96 geoid. None without a return, or
  // for a position the geodesy refuses (latitude beyond +-90).
  std::optional<GeoPoint> locate_target(const World& world, const GeoPoint& pod, double yaw_deg,
                                        double pitch_deg) const;

  void set_periodic(bool on) { periodic_ = on; }  // 0x000406
  bool periodic() const { return periodic_; }

 private:
  LaserConfig config_;
  bool periodic_ = false;
};

}  // namespace k40t::sim
