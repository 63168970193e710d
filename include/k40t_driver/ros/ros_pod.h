// The whole ROS driver for one pod: reads the parameters, builds the PodDriver and the pieces of
// ROS glue around it, and starts the link. The nodelet (k40t_driver/PodNodelet) and the
// standalone node (k40t_node) are each a few lines around one RosPod.
//
// Topics and services live in `nh` (the driver's namespace), parameters and dynamic_reconfigure
// in `private_nh`. Callbacks may run concurrently (services block while waiting for ACKs): give it
// a multi-threaded spinner or callback queue.
#pragma once

#include <memory>

#include <ros/node_handle.h>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/result.h"
#include "k40t_driver/ros/command_input.h"
#include "k40t_driver/ros/job_services.h"
#include "k40t_driver/ros/look_at_server.h"
#include "k40t_driver/ros/pod_actions.h"
#include "k40t_driver/ros/pod_diagnostics.h"
#include "k40t_driver/ros/pod_services.h"
#include "k40t_driver/ros/replay_input.h"
#include "k40t_driver/ros/ros_params.h"
#include "k40t_driver/ros/settings_services.h"
#include "k40t_driver/ros/settings_sync.h"
#include "k40t_driver/ros/target_locator.h"
#include "k40t_driver/ros/topic_publisher.h"

namespace k40t::driver {

class RosPod {
 public:
  // Fails with a readable message for a bad parameter or device URL; never for an absent or
  // silent pod (the link retries in the background and diagnostics say why).
  static Result<std::unique_ptr<RosPod>> create(ros::NodeHandle nh, ros::NodeHandle private_nh);
  ~RosPod();

 private:
  RosPod(ros::NodeHandle nh, ros::NodeHandle private_nh, const RosPodConfig& config,
         std::unique_ptr<PodDriver> driver);
  Status start();
  void on_pod_online();

  RosPodConfig config_;
  std::unique_ptr<PodDriver> driver_;
  std::unique_ptr<TopicPublisher> topics_;
  std::unique_ptr<SettingsSync> settings_;
  std::unique_ptr<PodDiagnostics> diagnostics_;
  std::unique_ptr<PodServices> services_;
  std::unique_ptr<SettingsServices> settings_services_;
  std::unique_ptr<JobServices> job_services_;
  std::unique_ptr<CommandInput> commands_;
  ros::Subscriber replay_;  // replay mode's input (raw/rx)
  std::unique_ptr<TargetLocator> locator_;
  std::unique_ptr<PodActions> actions_;    // live mode; shut down before the driver stops
  std::unique_ptr<LookAtServer> look_at_;  // live mode; the same
};

}  // namespace k40t::driver
