// What the driver's laser-target geolocation (ros/target_locator.h) keeps between messages,
// ROS-free: the last laser range (locate_pixel uses it for a pixel on the laser's axis), the laser
// target the driver located from it and the one the pod reports (TargetGpsAck), and the distance
// between the two when they are less than a second apart (docs/geo.md). Thread-safe.
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/geo/geodesy.h"
#include "k40t_driver/protocol/messages/flight_controller.h"

namespace k40t::driver {

// Two laser targets compared only when their stamps are at most this far apart.
constexpr StampNs kLaserTargetPairingNs = 1000000000;

class LaserTargetRecord {
 public:
  struct Summary {
    uint64_t located = 0;                  // laser targets the driver located
    std::string last_error;                // why the last range could not be located; empty: it was
    std::optional<double> disagreement_m;  // driver's vs pod's target, the last paired
  };

  // A laser range, before it is located.
  void range(double distance_m);
  std::optional<double> last_range_m() const;
  // The driver located the range stamped `stamp` at `where`, or could not (`error`).
  void located(const geo::Geodetic& where, StampNs stamp);
  void not_located(const std::string& error);
  // The pod's own answer; one that is not kOk, or whose altitude cannot be taken from the
  // geoid to the ellipsoid, is ignored.
  void pod_target(const protocol::TargetGpsAck& target, StampNs stamp);

  Summary summary() const;

 private:
  void compare_locked();

  mutable std::mutex mutex_;  // everything below
  std::optional<double> last_range_m_;
  std::optional<std::pair<geo::Geodetic, StampNs>> last_local_, last_pod_;
  Summary summary_;
};

}  // namespace k40t::driver
