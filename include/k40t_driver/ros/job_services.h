// Services for the camera's one-shot jobs that only the raw `send` service reached before:
// precise_reshoot (0x000307, in physical units; zoom and focal value default to the latest
// visible/status report, 0x000005) and tf_upgrade (0x00030C). Progress comes on reshoot/status
// and tf_card_upgrade/status (TopicPublisher).
#pragma once

#include <mutex>
#include <optional>
#include <vector>

#include <ros/node_handle.h>
#include <ros/service_server.h>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/operations/camera_operations.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver {

// The request in physical units -> 0x000307 (ReshootArgs, reshoot_request) is shared with the
// precise_reshoot action: operations/camera_operations.h.
using operations::reshoot_request;
using operations::ReshootArgs;

class JobServices {
 public:
  // Registers a visible-report handler: construct before PodDriver::start().
  JobServices(ros::NodeHandle nh, PodDriver& driver);

 private:
  std::optional<protocol::VisibleStatus> latest_visible() const;

  ros::NodeHandle nh_;
  PodDriver& driver_;
  std::vector<ros::ServiceServer> servers_;
  mutable std::mutex mutex_;
  std::optional<protocol::VisibleStatus> visible_;
};

}  // namespace k40t::driver
