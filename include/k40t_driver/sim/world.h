// The world the simulated pod looks at, fixed in the world frame of geometry.h (so turning the
// gimbal moves things across the image, zooming magnifies them, and the laser ranges them):
//   - flat ground `ground_height_m` below the pod, at ~20 degC with a gentle +-2.5 degC texture;
//   - a hot object: a sphere standing on the ground (a boiler or engine), hottest where it faces
//     the viewer, so the thermal maximum sits where its centre projects;
//   - a cold object: a pond on the ground, coldest at its centre;
//   - the sky: very cold, warmest at the horizon.
// Everything is analytic and deterministic; there is no randomness in the world.
#pragma once

#include <optional>

#include "k40t_driver/sim/geometry.h"

namespace k40t::sim {

// A round object on the ground, metres north and east of the take-off point.
struct GroundObject {
  double north_m = 0;
  double east_m = 0;
  double radius_m = 0;
  double temperature_degC = 0;
};

struct WorldConfig {
  double ground_height_m = 30;  // the ground is this far below the pod
  double ground_temperature_degC = 20;
  double ground_texture_degC = 2.5;  // amplitude of the ground's temperature pattern
  double sky_zenith_degC = -35;
  double sky_horizon_degC = -10;
  GroundObject hot{80, 20, 2, 85};   // a sphere; its temperature where it faces the viewer
  GroundObject cold{60, -30, 8, 2};  // a disc; its temperature at the centre, the rim blends in
};

enum class Surface { kSky, kGround, kHotObject, kColdObject };
const char* to_string(Surface surface);

struct Hit {
  Surface surface = Surface::kSky;
  std::optional<double> distance_m;  // none for the sky
  double temperature_degC = 0;
};

class World {
 public:
  explicit World(const WorldConfig& config = {}) : config_(config) {}

  const WorldConfig& config() const { return config_; }
  void set_ground_height(double metres) { config_.ground_height_m = metres; }
  // Where the hot object stands, metres north and east of the take-off point.
  void set_hot_object(double north_m, double east_m) {
    config_.hot.north_m = north_m;
    config_.hot.east_m = east_m;
  }
  // Where the pod is over the ground, relative to where it started (a moving vehicle): the
  // objects and the ground's pattern stay put while the pod moves (sim/ground_truth.h).
  void set_pod_offset(double north_m, double east_m) {
    pod_north_m_ = north_m;
    pod_east_m_ = east_m;
  }

  // What a ray from the pod (the origin) along the unit vector `dir` sees first.
  Hit trace(const Vec3& dir) const;

  // Relative to the pod, like everything above.
  Vec3 hot_object_centre() const;
  Vec3 cold_object_centre() const;

 private:
  double ground_temperature(double north_m, double east_m) const;

  WorldConfig config_;
  double pod_north_m_ = 0;
  double pod_east_m_ = 0;
};

}  // namespace k40t::sim
