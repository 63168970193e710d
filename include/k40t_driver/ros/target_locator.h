// The driver's own geolocation (docs/geo.md):
//   laser/target_local  sensor_msgs/NavSatFix  where the laser spot is: each laser range (ACK
//                       0x010400, status 0x020406) along the laser frame's x axis, taken to the
//                       vehicle frame by TF (~vehicle_frame, default the pod's base link) and to
//                       the Earth by the fix and attitude at the range's stamp; ENU covariance
//                       from the fix, ~attitude_sigma, ~pointing_sigma and ~range_sigma
//   locate_pixel        k40t_driver/LocatePixel  a pixel of the current image to a position: the
//                       camera_info of the pixel's view (camera_views.h: in split screen, the
//                       panel's) and TF given to the ROS-free rule driver/pixel_locator.h (the
//                       laser range on the laser's axis, or a horizontal plane)
//   located_point       geometry_msgs/PointStamped  the last located pixel, in its camera frame
//   located_fix         sensor_msgs/NavSatFix       the same on the Earth
// and a diagnostic "geolocation": the distance between laser/target_local and the pod's own
// answer (laser/target) when both are less than a second apart.
// Handlers are registered on the PodDriver like TopicPublisher's (frame stamps), so a replay
// regenerates laser/target_local.
#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_server.h>
#include <ros/subscriber.h>
#include <sensor_msgs/CameraInfo.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "k40t_driver/LocatePixel.h"
#include "k40t_driver/driver/laser_target_record.h"
#include "k40t_driver/driver/pixel_locator.h"
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/geo/ray_locator.h"
#include "k40t_driver/ros/camera_views.h"
#include "k40t_driver/ros/pod_diagnostics.h"
#include "k40t_driver/ros/ros_params.h"

namespace k40t::driver {

class TargetLocator {
 public:
  TargetLocator(ros::NodeHandle nh, const ros::NodeHandle& private_nh, PodDriver& driver,
                const RosPodConfig& config, PodDiagnostics& diagnostics);
  // Its TF buffer, for gimbal/look_at (one listener per driver).
  const tf2_ros::Buffer& tf() const { return tf_; }

 private:
  void on_range(double distance_m, StampNs stamp);
  bool locate_pixel(k40t_driver::LocatePixel::Request& req,
                    k40t_driver::LocatePixel::Response& res);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  PodDriver& driver_;
  FrameIds ids_;
  std::string vehicle_frame_;
  geo::RayUncertainty uncertainty_;
  PixelLocatorSetup pixel_setup_;  // locate_pixel's frames, uncertainty and laser-axis tolerance
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  ros::Publisher target_local_, located_point_, located_fix_;
  CameraViews camera_views_;
  ros::ServiceServer locate_pixel_;
  LaserTargetRecord record_;
};

}  // namespace k40t::driver
