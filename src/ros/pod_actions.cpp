#include "k40t_driver/ros/pod_actions.h"

#include <cmath>
#include <limits>

namespace k40t::driver {

namespace p = protocol;
namespace ops = operations;

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

template <class Req>
void PodActions::send(const Req& request, std::function<void(const session::AckResult&)> done) {
  driver_.request_async(request, std::move(done));
}

template <class Req>
std::string PodActions::stop_with(const Req& request, const std::string& what) {
  const session::AckResult stopped = driver_.request(request);
  return stopped.ok() ? what + " stopped" : what + " not stopped: " + stopped.message;
}

template <class Action, class Op, class Req, class Feedback>
std::unique_ptr<OperationServer<Action, Op>> PodActions::timeout_only_action(
    ros::NodeHandle& nh, const std::string& name, const Req& request, Feedback feedback) {
  typename OperationServer<Action, Op>::Binding binding;
  binding.create = [](const auto& goal, double now_s) { return Op::create(goal.timeout, now_s); };
  binding.send = sends(request);
  binding.feedback = std::move(feedback);
  return std::make_unique<OperationServer<Action, Op>>(nh, name, std::move(binding));
}

PodActions::PodActions(ros::NodeHandle nh, PodDriver& driver) : driver_(driver) {
  create_gimbal_actions(nh);
  create_camera_actions(nh);
  create_maintenance_actions(nh);
  subscribe_status();
}

PodActions::~PodActions() {
  shutdown();
}

void PodActions::start() {
  move_->start();
  calibrate_->start();
  zoom_->start();
  reshoot_->start();
  format_->start();
  upgrade_->start();
}

void PodActions::shutdown() {
  move_->shutdown();
  calibrate_->shutdown();
  zoom_->shutdown();
  reshoot_->shutdown();
  format_->shutdown();
  upgrade_->shutdown();
}

void PodActions::create_gimbal_actions(ros::NodeHandle& nh) {
  using Server = OperationServer<k40t_driver::GimbalMoveToAction, ops::GimbalMove>;
  Server::Binding move;
  move.create = [](const k40t_driver::GimbalMoveToGoal& goal, double now_s) {
    ops::GimbalMoveGoal g;
    g.pitch_rad = goal.pitch;
    g.yaw_rad = goal.yaw;
    g.tolerance_rad = goal.tolerance;
    g.timeout_s = goal.timeout;
    return ops::GimbalMove::create(g, now_s);
  };
  move.send = sends_its_request();
  move.feedback = [](const ops::GimbalMove& op, k40t_driver::GimbalMoveToFeedback& feedback) {
    const ops::JointAngles joints = op.joints().value_or(ops::JointAngles{kNaN, kNaN, kNaN});
    feedback.pitch = joints.pitch_rad;
    feedback.yaw = joints.yaw_rad;
    feedback.roll = joints.roll_rad;
    feedback.error = op.joints() ? op.error_rad() : kNaN;
  };
  move.result = [](const ops::GimbalMove& op, k40t_driver::GimbalMoveToResult& result) {
    result.pitch = op.joints() ? op.joints()->pitch_rad : kNaN;
    result.yaw = op.joints() ? op.joints()->yaw_rad : kNaN;
  };
  // Both axes "stop" (0x000010): the gimbal holds where it is.
  move.stop = [this] { return stop_with(p::GimbalControlRequest{}, "gimbal"); };
  move_ = std::make_unique<Server>(nh, "gimbal/move_to", std::move(move));

  using CalibrationServer =
      OperationServer<k40t_driver::GimbalCalibrateAction, ops::GimbalCalibration>;
  CalibrationServer::Binding calibrate;
  calibrate.create = [this](const k40t_driver::GimbalCalibrateGoal& goal, double now_s) {
    return ops::GimbalCalibration::create(goal.kind, goal.timeout, now_s,
                                          driver_.conventions().conventions().calibration_end);
  };
  calibrate.send = [this](const ops::GimbalCalibration& op, auto done) {
    switch (op.kind()) {
      case ops::CalibrationKind::kDrift:
        return send(p::GimbalDriftCalibrationRequest{}, done);
      case ops::CalibrationKind::kLinear:
        return send(p::GimbalLinearCalibrationRequest{}, done);
      case ops::CalibrationKind::kAccelerometer:
        return send(p::GimbalAccelerationCalibrationRequest{}, done);
    }
  };
  calibrate.feedback = [](const ops::GimbalCalibration& op,
                          k40t_driver::GimbalCalibrateFeedback& feedback) {
    feedback.progress = static_cast<int8_t>(op.progress_percent());
  };
  calibrate_ = std::make_unique<CalibrationServer>(nh, "gimbal/calibrate", std::move(calibrate));
}

void PodActions::create_camera_actions(ros::NodeHandle& nh) {
  using ZoomServer = OperationServer<k40t_driver::ZoomToAction, ops::ZoomTo>;
  ZoomServer::Binding zoom;
  zoom.create = [](const k40t_driver::ZoomToGoal& goal, double now_s) {
    return ops::ZoomTo::create(goal.ratio, goal.timeout, now_s);
  };
  zoom.send = sends_its_request();
  zoom.feedback = [](const ops::ZoomTo& op, k40t_driver::ZoomToFeedback& feedback) {
    feedback.ratio = op.ratio_x().value_or(kNaN);
  };
  zoom.result = [](const ops::ZoomTo& op, k40t_driver::ZoomToResult& result) {
    result.ratio = op.ratio_x().value_or(kNaN);
  };
  zoom.stop = [this] {
    p::ContinuousZoomRequest stop;
    stop.command = p::ZoomCommand::kStop;
    return stop_with(stop, "zoom");
  };
  zoom_ = std::make_unique<ZoomServer>(nh, "zoom_to", std::move(zoom));

  using ReshootServer = OperationServer<k40t_driver::PreciseReshootAction, ops::PreciseReshoot>;
  ReshootServer::Binding reshoot;
  reshoot.create = [this](const k40t_driver::PreciseReshootGoal& goal, double now_s) {
    ops::PreciseReshootGoal g;
    g.args.lens = goal.lens;
    g.args.resolution = goal.resolution;
    g.args.zoom_ratio = goal.zoom_ratio;
    g.args.focal_length_mm = goal.focal_length_mm;
    g.args.folder = goal.folder;
    g.args.name = goal.name;
    g.timeout_s = goal.timeout;
    Result<ops::PreciseReshoot> created = [&] {
      std::lock_guard<std::mutex> lock(visible_mutex_);
      return ops::PreciseReshoot::create(g, latest_visible_, now_s);
    }();
    // The goal's own errors first; then the mode, which would leave the pod silent.
    if (!created) return created;
    const Status allowed = capture_mode_.allows(p::CaptureMode::kPhoto, "precise re-shoots");
    return allowed ? std::move(created) : Result<ops::PreciseReshoot>::fail(allowed.message());
  };
  reshoot.send = sends_its_request();
  reshoot_ = std::make_unique<ReshootServer>(nh, "precise_reshoot", std::move(reshoot));
}

void PodActions::create_maintenance_actions(ros::NodeHandle& nh) {
  format_ = timeout_only_action<k40t_driver::FormatSdAction, ops::SdFormat>(
      nh, "format_sd", p::FormatSdRequest{},
      [](const ops::SdFormat& op, k40t_driver::FormatSdFeedback& feedback) {
        feedback.reports = static_cast<uint32_t>(op.tracker().reports());
      });
  upgrade_ = timeout_only_action<k40t_driver::TfUpgradeAction, ops::TfUpgrade>(
      nh, "tf_upgrade", p::TfCardUpgradeRequest{},
      [](const ops::TfUpgrade& op, k40t_driver::TfUpgradeFeedback& feedback) {
        feedback.progress = static_cast<int8_t>(op.progress_percent());
      });
}

void PodActions::subscribe_status() {
  driver_.on_tx_frame([this](const p::FrameView& frame, StampNs) {
    capture_mode_.frame_sent(frame, driver_.codec());
  });
  driver_.on_rx_frame([this](const p::FrameView& frame, StampNs) {
    capture_mode_.frame_received(frame, driver_.codec());
  });
  driver_.on<p::GimbalAttitude>([this](const p::GimbalAttitude& m, StampNs) {
    move_->feed([&](ops::GimbalMove& op) { op.on_attitude(m); });
  });
  driver_.on<p::CameraUpgradeStatus>([this](const p::CameraUpgradeStatus& m, StampNs) {
    calibrate_->feed([&](ops::GimbalCalibration& op) { op.on_status(m); });
    upgrade_->feed([&](ops::TfUpgrade& op) { op.on_progress(m); });
  });
  driver_.on<p::VisibleStatus>([this](const p::VisibleStatus& m, StampNs) {
    {
      std::lock_guard<std::mutex> lock(visible_mutex_);
      latest_visible_ = m;
    }
    zoom_->feed([&](ops::ZoomTo& op) { op.on_visible(m); });
  });
  driver_.on<p::ZoomStatus>([this](const p::ZoomStatus& m, StampNs) {
    zoom_->feed([&](ops::ZoomTo& op) { op.on_status(m); });
  });
  driver_.on<p::PreciseReshootStatus>([this](const p::PreciseReshootStatus& m, StampNs) {
    reshoot_->feed([&](ops::PreciseReshoot& op) { op.on_status(m); });
  });
  driver_.on<p::SdFormatStatus>([this](const p::SdFormatStatus& m, StampNs) {
    format_->feed([&](ops::SdFormat& op) { op.on_status(m); });
  });
  driver_.on<p::TfCardUpgradeStatus>([this](const p::TfCardUpgradeStatus& m, StampNs) {
    upgrade_->feed([&](ops::TfUpgrade& op) { op.on_status(m); });
  });
}

}  // namespace k40t::driver
