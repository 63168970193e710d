// What gimbal/look_at and gimbal/look_at_point follow, as ROS glue: a goal's target checked and
// converted (a WGS-84 position's sea-level altitude made an ellipsoid height with the project's
// geoid), put in the gimbal's base frame at a control step (TF for a point in any frame; the
// vehicle's fix and attitude from the driver's history for a WGS-84 position), and the marker
// that shows it in rviz (docs/ros_interface.md "Looking at a place").
#pragma once

#include <string>

#include <geometry_msgs/PointStamped.h>
#include <tf2_ros/buffer.h>
#include <visualization_msgs/MarkerArray.h>

#include "k40t_driver/LookAtGoal.h"
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/geo/look_at_geometry.h"

namespace k40t::driver {

struct LookAtTarget {
  bool wgs84 = false;
  geometry_msgs::PointStamped point;  // !wgs84: in any TF frame
  geo::Geodetic position;             // wgs84: height above the ellipsoid
};

// The goal's target, or why it is refused (an unknown type or datum, a position check_geodetic()
// refuses, a point without a frame, no geoid for an MSL altitude).
Result<LookAtTarget> target_of_goal(const k40t_driver::LookAtGoal& goal);
// A look_at_point message's target, or why it is refused.
Result<LookAtTarget> target_of_point(const geometry_msgs::PointStamped& point);

// The target in the gimbal's base frame at a step, and how old what it was computed from is.
struct TargetInBase {
  geo::Vector3 vector;
  double age_s = 0;
};

class TargetResolver {
 public:
  // `base_frame`: the gimbal's (k40t_base_link); `vehicle_frame`: the frame the attitude input
  // describes (~vehicle_frame), TF between the two.
  TargetResolver(const tf2_ros::Buffer& tf, const PodDriver& driver, std::string base_frame,
                 std::string vehicle_frame)
      : tf_(tf),
        driver_(driver),
        base_frame_(std::move(base_frame)),
        vehicle_frame_(std::move(vehicle_frame)) {}

  Result<TargetInBase> resolve(const LookAtTarget& target, const ros::Time& now) const;
  const std::string& base_frame() const { return base_frame_; }

 private:
  Result<TargetInBase> point_in_base(const geometry_msgs::PointStamped& point,
                                     const ros::Time& now) const;
  Result<TargetInBase> wgs84_in_base(const geo::Geodetic& position, const ros::Time& now) const;

  const tf2_ros::Buffer& tf_;
  const PodDriver& driver_;
  std::string base_frame_;
  std::string vehicle_frame_;
};

// The target (a sphere), the line of sight from the gimbal to it (green) and the boresight as far
// (yellow: where the camera looks), in the base frame; `aim` none: no boresight line.
visualization_msgs::MarkerArray look_at_markers(const std::string& base_frame,
                                                const ros::Time& stamp, const geo::Vector3& target,
                                                const std::optional<geo::GimbalAim>& aim);
// Deletes them (following ended).
visualization_msgs::MarkerArray clear_look_at_markers(const std::string& base_frame);

}  // namespace k40t::driver
