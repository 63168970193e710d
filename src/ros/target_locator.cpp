#include "k40t_driver/ros/target_locator.h"

#include <cmath>

#include <geometry_msgs/PointStamped.h>
#include <ros/console.h>

#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/ros/geo_glue.h"

namespace k40t::driver {

namespace {

constexpr StampNs kSecondNs = 1000000000;

ros::Time to_ros_time(StampNs stamp) {
  ros::Time t;
  t.fromNSec(stamp > 0 ? static_cast<uint64_t>(stamp) : 0);
  return t;
}

}  // namespace

TargetLocator::TargetLocator(ros::NodeHandle nh, const ros::NodeHandle& private_nh,
                             PodDriver& driver, const RosPodConfig& config,
                             PodDiagnostics& diagnostics)
    : driver_(driver),
      ids_(config.ids),
      tf_(ros::Duration(30.0)),
      listener_(tf_),
      camera_views_(nh) {
  vehicle_frame_ = private_nh.param<std::string>("vehicle_frame", ids_.base);
  uncertainty_ = read_uncertainty(private_nh);
  private_nh.param("laser_axis_tolerance_px", laser_axis_tolerance_px_, laser_axis_tolerance_px_);

  target_local_ = nh.advertise<sensor_msgs::NavSatFix>("laser/target_local", 10);
  located_point_ = nh.advertise<geometry_msgs::PointStamped>("located_point", 1, true);
  located_fix_ = nh.advertise<sensor_msgs::NavSatFix>("located_fix", 1, true);
  auto range = [this](const auto& m, StampNs s) {
    if (m.code == protocol::ResponseCode::kOk && m.distance_m > 0) on_range(m.distance_m, s);
  };
  driver.on<protocol::LaserRangeAck>(range);
  driver.on<protocol::LaserPeriodicRangeStatus>(range);
  driver.on<protocol::TargetGpsAck>(
      [this](const protocol::TargetGpsAck& m, StampNs s) { on_pod_target(m, s); });
  locate_pixel_ = nh.advertiseService("locate_pixel", &TargetLocator::locate_pixel, this);
  diagnostics.add_task("geolocation", [this](auto& stat) { diagnose(stat); });
}

void TargetLocator::on_range(double distance_m, StampNs stamp) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    last_range_ = {distance_m, stamp};
  }
  const ros::Time t = to_ros_time(stamp);
  Result<geo::VehiclePose> pose = vehicle_pose(driver_.vehicle_state_at(stamp));
  Result<geo::BodyRay> ray = pose ? ray_in_vehicle(tf_, vehicle_frame_, ids_.laser, t, {1, 0, 0})
                                  : Result<geo::BodyRay>::fail(pose.error());
  Result<geo::Located> located =
      ray ? geo::locate_at_range(pose.value(), ray.value(), distance_m, uncertainty_)
          : Result<geo::Located>::fail(ray.error());
  std::lock_guard<std::mutex> lock(mutex_);
  if (!located) {
    last_error_ = located.error();
    return;
  }
  last_error_.clear();
  ++located_;
  last_local_ = {located->position, stamp};
  compare_locked();
  target_local_.publish(to_nav_sat_fix(located.value(), t, ids_.laser));
}

void TargetLocator::on_pod_target(const protocol::TargetGpsAck& target, StampNs stamp) {
  if (target.code != protocol::ResponseCode::kOk) return;
  const Result<double> h = geo::Geoid::egm96().ellipsoid_from_msl(
      target.latitude_deg, target.longitude_deg, target.altitude_m);
  if (!h) return;
  std::lock_guard<std::mutex> lock(mutex_);
  last_pod_ = {{target.latitude_deg, target.longitude_deg, h.value()}, stamp};
  compare_locked();
}

void TargetLocator::compare_locked() {
  if (!last_local_ || !last_pod_) return;
  if (std::llabs(last_local_->second - last_pod_->second) > kSecondNs) return;
  disagreement_m_ = geo::distance_m(last_local_->first, last_pod_->first);
}

void TargetLocator::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  std::lock_guard<std::mutex> lock(mutex_);
  stat.add("laser targets located", located_);
  stat.add("last error", last_error_.empty() ? "none" : last_error_);
  stat.add("distance to the pod's laser target (m)", disagreement_m_ ? *disagreement_m_ : -1.0);
  if (!last_error_.empty() && located_ == 0) {
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "no laser target located: " + last_error_);
  } else {
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
  }
}

bool TargetLocator::locate_pixel(k40t_driver::LocatePixel::Request& req,
                                 k40t_driver::LocatePixel::Response& res) {
  auto fail = [&](const std::string& why) {
    res.success = false;
    res.message = why;
    return true;
  };
  std::optional<std::pair<double, StampNs>> range;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    range = last_range_;
  }
  if (!std::isfinite(req.u) || !std::isfinite(req.v)) return fail("u, v must be finite");
  // The image's camera_info, or in split screen the panel's that holds the pixel.
  const Result<sensor_msgs::CameraInfo> info = camera_views_.for_pixel(req.u, req.v);
  if (!info) return fail(info.error());
  if (req.u < 0 || req.v < 0 || (info->width > 0 && req.u > info->width) ||
      (info->height > 0 && req.v > info->height))
    return fail("u, v must be inside the " + std::to_string(info->width) + "x" +
                std::to_string(info->height) + " image");
  const camera::CameraModel lens = camera_model(info.value());
  // Undistorted (OpenCV, with the camera_info's D) normalised coordinates of the pixel.
  const Result<std::array<double, 2>> normalised = camera::pixel_to_normalised(lens, req.u, req.v);
  if (!normalised) return fail(normalised.error());
  if (req.plane_reference > k40t_driver::LocatePixel::Request::MSL)
    return fail("plane_reference must be 0 (ABOVE_TAKEOFF) or 1 (MSL)");
  if (!std::isfinite(req.plane_height)) return fail("plane_height must be finite");

  const ros::Time stamp = info->header.stamp;
  const VehicleState state = driver_.vehicle_state_at(static_cast<StampNs>(stamp.toNSec()));
  const Result<geo::VehiclePose> pose = vehicle_pose(state);
  if (!pose) return fail(pose.error());
  const std::string& camera = info->header.frame_id;
  // Optical frame: z forward, x right, y down.
  const geo::Vector3 optical{(*normalised)[0], (*normalised)[1], 1.0};
  const Result<geo::BodyRay> ray = ray_in_vehicle(tf_, vehicle_frame_, camera, stamp, optical);
  if (!ray) return fail(ray.error());

  // Is the pixel on the laser axis? The laser's x axis projected into this image.
  bool on_axis = false;
  if (req.use_laser && range) {
    const Result<geo::BodyRay> laser = ray_in_vehicle(tf_, camera, ids_.laser, stamp, {1, 0, 0});
    const Result<std::array<double, 2>> spot =
        laser ? camera::project_ray(lens, laser->direction)
              : Result<std::array<double, 2>>::fail(laser.error());
    if (spot)
      on_axis = std::hypot((*spot)[0] - req.u, (*spot)[1] - req.v) <= laser_axis_tolerance_px_;
  }
  Result<geo::Located> located = Result<geo::Located>::fail("not located");
  if (on_axis) {
    located = geo::locate_at_range(pose.value(), ray.value(), range->first, uncertainty_);
  } else {
    const Result<double> plane_h = plane_height_ellipsoid(
        state,
        req.plane_reference == k40t_driver::LocatePixel::Request::ABOVE_TAKEOFF
            ? PlaneReference::kAboveTakeoff
            : PlaneReference::kMeanSeaLevel,
        req.plane_height);
    if (!plane_h) return fail(plane_h.error());
    located = geo::locate_on_plane(pose.value(), ray.value(), plane_h.value() - state.altitude_m,
                                   uncertainty_);
    if (!located)
      return fail("the pixel's ray misses the ground plane (above the horizon or beyond 10 km)");
  }
  if (!located) return fail(located.error());
  const Result<double> msl = geo::Geoid::egm96().msl_from_ellipsoid(
      located->position.latitude_deg, located->position.longitude_deg,
      located->position.height_ellipsoid_m);
  res.success = true;
  res.message = "ok";
  res.fix = to_nav_sat_fix(located.value(), stamp, camera);
  res.altitude_msl = msl ? msl.value() : std::nan("");
  res.slant_range = located->slant_range_m;
  res.on_laser_axis = on_axis;
  // For rviz: the point in the camera frame, along the pixel's ray.
  geometry_msgs::PointStamped point;
  point.header = res.fix.header;
  const double n = std::sqrt(optical[0] * optical[0] + optical[1] * optical[1] + 1.0);
  point.point.x = optical[0] / n * located->slant_range_m;
  point.point.y = optical[1] / n * located->slant_range_m;
  point.point.z = optical[2] / n * located->slant_range_m;
  located_point_.publish(point);
  located_fix_.publish(res.fix);
  return true;
}

}  // namespace k40t::driver
