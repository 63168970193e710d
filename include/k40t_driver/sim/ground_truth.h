// The simulated world on the Earth: where the take-off point is (WGS 84), how the vehicle
// carrying the pod moves (vehicle_motion.h: a constant velocity from the take-off point, or a
// circle, at the world's ground height above it), and so the true geodetic position of the pod, of
// the world's objects and of the laser spot at any model time. Also the geotag log: for each photo,
// the pod's true position when it was taken and when the host's GPS answer (0x010310) arrived, and
// that answer, so the geotag error is measured against the truth. And the flight data the host last
// sent in the laser-target request 0x000320 (ground speed, climb rate...), so a test can compare it
// with what it fed the driver.
//
// The world frame of world.h is the pod's (x north, y east, z up, pod at the origin); the truth
// frame here is the local ENU frame of the take-off point on the ground (geo/geodesy.h), in the
// same axis order as world.h: x north, y east, z up.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/geo/geodesy.h"
#include "k40t_driver/sim/geometry.h"
#include "k40t_driver/sim/vehicle_motion.h"

namespace k40t::sim {

struct VehicleConfig {
  double origin_latitude_deg = 47.3769;  // the take-off point, on the ground
  double origin_longitude_deg = 8.5417;
  double origin_ground_msl_m = 408.0;  // the ground's height above mean sea level
  double velocity_north_m_s = 0;       // constant, from model time 0 (until `fly` or `orbit`)
  double velocity_east_m_s = 0;
};

// A true position: geodetic (ellipsoid height) and its height above sea level.
struct TruePoint {
  geo::Geodetic geodetic;
  double msl_m = 0;
};

struct GeotagRecord {
  uint64_t photo_id = 0;
  Vec3 at_photo;                    // pod in the truth frame when the photo was taken
  std::optional<Vec3> at_answer;    // ... when the GPS answer arrived
  std::optional<TruePoint> answer;  // what the host answered
};

// The flight data of the last 0x000320 the pod received, and how many it received.
struct ReceivedFlightData {
  uint64_t requests = 0;
  double ground_speed_m_s = 0;
  double climb_rate_m_s = 0;
  double heading_deg = 0;
  double airspeed_m_s = 0;
  double throttle_percent = 0;
};

class GroundTruth {
 public:
  explicit GroundTruth(const VehicleConfig& config = {});

  const VehicleConfig& config() const { return config_; }
  // The pod's position in the truth frame at model time t, `height_m` above the ground.
  Vec3 pod_position(double t_s, double height_m) const;
  Vec3 velocity(double t_s) const { return motion_.velocity(t_s); }
  // The vehicle's motion from now on (control commands `fly`, `orbit`).
  VehicleMotion& motion() { return motion_; }
  // A point of the truth frame on the Earth; fails only without the geoid (proj-data).
  Result<TruePoint> to_earth(const Vec3& point) const;
  // The inverse, for an answer given in latitude, longitude and height above sea level.
  Result<Vec3> from_earth(double latitude_deg, double longitude_deg, double msl_m) const;

  void photo_taken(uint64_t photo_id, const Vec3& pod);
  void photo_answered(uint64_t photo_id, const Vec3& pod, double latitude_deg, double longitude_deg,
                      double msl_m);
  const std::vector<GeotagRecord>& geotags() const { return geotags_; }
  // One line: per answered photo, the error of the answer against the truth when the photo was
  // taken, and how far the pod had moved by the time the answer arrived (what answering with
  // the latest state would at best have been off by).
  std::string describe_geotags() const;

  void flight_data_received(ReceivedFlightData data);
  const ReceivedFlightData& received_flight_data() const { return received_; }

 private:
  VehicleConfig config_;
  VehicleMotion motion_;
  std::optional<geo::LocalFrame> frame_;  // none without the geoid
  std::vector<GeotagRecord> geotags_;
  ReceivedFlightData received_;
};

}  // namespace k40t::sim
