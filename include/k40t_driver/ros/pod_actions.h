// The driver's actions (action/*.action, docs/ros_interface.md "Actions"): the pod's long
// operations with feedback, a result, cancel where the pod can stop and a timeout:
//   gimbal/move_to, gimbal/calibrate, zoom_to, format_sd, precise_reshoot, tf_upgrade.
// The decisions are the ROS-free operations/ classes'; this is their glue: the status handlers
// (registered on the PodDriver at construction, before the link starts) feed the running goal,
// and each OperationServer publishes what its operation says.
//
// Lifetime: construct before PodDriver::start(), start() after, shutdown() before
// PodDriver::stop() (it ends running goals and joins their threads).
#pragma once

#include <memory>
#include <mutex>
#include <optional>

#include <ros/node_handle.h>

#include "k40t_driver/FormatSdAction.h"
#include "k40t_driver/GimbalCalibrateAction.h"
#include "k40t_driver/GimbalMoveToAction.h"
#include "k40t_driver/PreciseReshootAction.h"
#include "k40t_driver/TfUpgradeAction.h"
#include "k40t_driver/ZoomToAction.h"
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/operations/camera_operations.h"
#include "k40t_driver/operations/capture_mode_guard.h"
#include "k40t_driver/operations/gimbal_operations.h"
#include "k40t_driver/ros/operation_server.h"

namespace k40t::driver {

class PodActions {
 public:
  PodActions(ros::NodeHandle nh, PodDriver& driver);
  ~PodActions();
  PodActions(const PodActions&) = delete;
  PodActions& operator=(const PodActions&) = delete;

  void start();
  void shutdown();

 private:
  void create_gimbal_actions(ros::NodeHandle& nh);
  void create_camera_actions(ros::NodeHandle& nh);
  void create_maintenance_actions(ros::NodeHandle& nh);
  void subscribe_status();
  // Sends `request` asynchronously; the ACK goes to `done`.
  template <class Req>
  void send(const Req& request, std::function<void(const session::AckResult&)> done);
  // A binding's send: always `request` / the operation's own request().
  template <class Req>
  auto sends(Req request) {
    return [this, request](const auto&, auto done) { send(request, done); };
  }
  auto sends_its_request() {
    return [this](const auto& op, auto done) { send(op.request(), done); };
  }
  // The server of an action whose goal is only its timeout and whose request is always `request`.
  template <class Action, class Op, class Req, class Feedback>
  std::unique_ptr<OperationServer<Action, Op>> timeout_only_action(ros::NodeHandle& nh,
                                                                   const std::string& name,
                                                                   const Req& request,
                                                                   Feedback feedback);
  // Sends a stopping request and says whether the pod took it, for a cancel's message.
  template <class Req>
  std::string stop_with(const Req& request, const std::string& what);

  PodDriver& driver_;
  mutable std::mutex visible_mutex_;
  std::optional<protocol::VisibleStatus> latest_visible_;
  // precise_reshoot is a photo request: in video mode the pod does not answer it (3.2.4.1).
  operations::CaptureModeGuard capture_mode_;

  std::unique_ptr<OperationServer<k40t_driver::GimbalMoveToAction, operations::GimbalMove>> move_;
  std::unique_ptr<
      OperationServer<k40t_driver::GimbalCalibrateAction, operations::GimbalCalibration>>
      calibrate_;
  std::unique_ptr<OperationServer<k40t_driver::ZoomToAction, operations::ZoomTo>> zoom_;
  std::unique_ptr<OperationServer<k40t_driver::PreciseReshootAction, operations::PreciseReshoot>>
      reshoot_;
  std::unique_ptr<OperationServer<k40t_driver::FormatSdAction, operations::SdFormat>> format_;
  std::unique_ptr<OperationServer<k40t_driver::TfUpgradeAction, operations::TfUpgrade>> upgrade_;
};

}  // namespace k40t::driver
