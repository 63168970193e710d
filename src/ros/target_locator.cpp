#include "k40t_driver/ros/target_locator.h"

#include <cmath>

#include <geometry_msgs/PointStamped.h>
#include <ros/console.h>

#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/ros/geo_glue.h"

namespace k40t::driver {

namespace {

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
      // On the node's callback queue, not a thread of its own: the listener's thread polls its
      // queue every 10 ms (100 wake-ups a second, a quarter of the driver's CPU at full
      // telemetry) while the spinner's threads are idle.
      listener_(tf_, nh, false),
      camera_views_(nh) {
  vehicle_frame_ = private_nh.param<std::string>("vehicle_frame", ids_.base);
  uncertainty_ = read_uncertainty(private_nh);
  pixel_setup_ = {
      vehicle_frame_, ids_.laser, uncertainty_,
      private_nh.param("laser_axis_tolerance_px", pixel_setup_.laser_axis_tolerance_px)};

  target_local_ = nh.advertise<sensor_msgs::NavSatFix>("laser/target_local", 10);
  located_point_ = nh.advertise<geometry_msgs::PointStamped>("located_point", 1, true);
  located_fix_ = nh.advertise<sensor_msgs::NavSatFix>("located_fix", 1, true);
  auto range = [this](const auto& m, StampNs s) {
    if (m.code == protocol::ResponseCode::kOk && m.distance_m > 0) on_range(m.distance_m, s);
  };
  driver.on<protocol::LaserRangeAck>(range);
  driver.on<protocol::LaserPeriodicRangeStatus>(range);
  // An OK answer at 0 deg, 0 deg is no target unless the pod's zeros are a position
  // (laser_target_zeros, docs/protocol/decisions.md#conventions).
  driver.on<protocol::TargetGpsAck>([this, zeros = driver.codec().conventions.laser_target_zeros](
                                        const protocol::TargetGpsAck& m, StampNs s) {
    if (!protocol::laser_target_no_return(m, zeros)) record_.pod_target(m, s);
  });
  locate_pixel_ = nh.advertiseService("locate_pixel", &TargetLocator::locate_pixel, this);
  diagnostics.add_task("geolocation", [this](auto& stat) { diagnose(stat); });
}

void TargetLocator::on_range(double distance_m, StampNs stamp) {
  record_.range(distance_m);
  const ros::Time t = to_ros_time(stamp);
  Result<geo::VehiclePose> pose = vehicle_pose(driver_.vehicle_state_at(stamp));
  Result<geo::BodyRay> ray = pose ? ray_in_vehicle(tf_, vehicle_frame_, ids_.laser, t, {1, 0, 0})
                                  : Result<geo::BodyRay>::fail(pose.error());
  Result<geo::Located> located =
      ray ? geo::locate_at_range(pose.value(), ray.value(), distance_m, uncertainty_)
          : Result<geo::Located>::fail(ray.error());
  if (!located) {
    record_.not_located(located.error());
    return;
  }
  record_.located(located->position, stamp);
  target_local_.publish(to_nav_sat_fix(located.value(), t, ids_.laser));
}

void TargetLocator::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  const LaserTargetRecord::Summary s = record_.summary();
  stat.add("laser targets located", s.located);
  stat.add("last error", s.last_error.empty() ? "none" : s.last_error);
  stat.add("distance to the pod's laser target (m)", s.disagreement_m ? *s.disagreement_m : -1.0);
  if (!s.last_error.empty() && s.located == 0) {
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "no laser target located: " + s.last_error);
  } else {
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
  }
}

bool TargetLocator::locate_pixel(k40t_driver::LocatePixel::Request& req,
                                 k40t_driver::LocatePixel::Response& res) {
  const std::optional<double> range_m = record_.last_range_m();
  res.success = false;
  if (!std::isfinite(req.u) || !std::isfinite(req.v)) {
    res.message = "u, v must be finite";
    return true;
  }
  // The image's camera_info, or in split screen the panel's that holds the pixel.
  const Result<sensor_msgs::CameraInfo> info = camera_views_.for_pixel(req.u, req.v);
  if (!info) {
    res.message = info.error();
    return true;
  }
  const ros::Time stamp = info->header.stamp;
  const CameraView view{camera_model(info.value()), info->width, info->height,
                        info->header.frame_id};
  const FrameRay frame_ray = [&](const std::string& target, const std::string& source,
                                 const geo::Vector3& direction) {
    return ray_in_vehicle(tf_, target, source, stamp, direction);
  };
  const PixelQuery query{req.u, req.v, req.plane_reference, req.plane_height, req.use_laser != 0};
  const Result<PixelLocation> where = driver::locate_pixel(
      query, view, driver_.vehicle_state_at(static_cast<StampNs>(stamp.toNSec())), range_m,
      frame_ray, pixel_setup_);
  if (!where) {
    res.message = where.error();
    return true;
  }
  res.success = true;
  res.message = "ok";
  res.fix = to_nav_sat_fix(where->located, stamp, view.frame);
  res.altitude_msl = where->altitude_msl ? *where->altitude_msl : std::nan("");
  res.slant_range = where->located.slant_range_m;
  res.on_laser_axis = where->on_laser_axis;
  // For rviz: the point in the camera frame, along the pixel's ray.
  geometry_msgs::PointStamped point;
  point.header = res.fix.header;
  const geo::Vector3& optical = where->optical;
  const double n = std::sqrt(optical[0] * optical[0] + optical[1] * optical[1] + 1.0);
  point.point.x = optical[0] / n * where->located.slant_range_m;
  point.point.y = optical[1] / n * where->located.slant_range_m;
  point.point.z = optical[2] / n * where->located.slant_range_m;
  located_point_.publish(point);
  located_fix_.publish(res.fix);
  return true;
}

}  // namespace k40t::driver
