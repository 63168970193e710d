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

#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "k40t_driver/ros/pod_driver.h"

namespace k40t::driver {

// The service's request in physical units -> 0x000307; `latest` is the newest visible report,
// which supplies a zoom or focal value given as 0. Fails naming the field and its range.
struct ReshootArgs {
  uint8_t lens = 0;
  uint8_t resolution = 0;
  double zoom_ratio = 0;
  double focal_length_mm = 0;
  std::string folder;
  std::string name;
};
Result<protocol::PreciseReshootRequest> reshoot_request(
    const ReshootArgs& args, const std::optional<protocol::VisibleStatus>& latest);

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
