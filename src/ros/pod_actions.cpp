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
  move.send = [this](const ops::GimbalMove& op, auto done) { send(op.request(), done); };
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
  calibrate.create = [](const k40t_driver::GimbalCalibrateGoal& goal, double now_s) {
    return ops::GimbalCalibration::create(goal.kind, goal.timeout, now_s);
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
    feedback.status = op.tracker().status_text();
  };
  calibrate.result = [](const ops::GimbalCalibration&, k40t_driver::GimbalCalibrateResult&) {};
  calibrate_ = std::make_unique<CalibrationServer>(nh, "gimbal/calibrate", std::move(calibrate));
}

void PodActions::create_camera_actions(ros::NodeHandle& nh) {
  using ZoomServer = OperationServer<k40t_driver::ZoomToAction, ops::ZoomTo>;
  ZoomServer::Binding zoom;
  zoom.create = [](const k40t_driver::ZoomToGoal& goal, double now_s) {
    return ops::ZoomTo::create(goal.ratio, goal.timeout, now_s);
  };
  zoom.send = [this](const ops::ZoomTo& op, auto done) { send(op.request(), done); };
  zoom.feedback = [](const ops::ZoomTo& op, k40t_driver::ZoomToFeedback& feedback) {
    feedback.ratio = op.ratio_x().value_or(kNaN);
    feedback.status = op.tracker().status_text();
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
    std::lock_guard<std::mutex> lock(visible_mutex_);
    return ops::PreciseReshoot::create(g, latest_visible_, now_s);
  };
  reshoot.send = [this](const ops::PreciseReshoot& op, auto done) { send(op.request(), done); };
  reshoot.feedback = [](const ops::PreciseReshoot& op,
                        k40t_driver::PreciseReshootFeedback& feedback) {
    feedback.status = op.tracker().status_text();
  };
  reshoot.result = [](const ops::PreciseReshoot&, k40t_driver::PreciseReshootResult&) {};
  reshoot_ = std::make_unique<ReshootServer>(nh, "precise_reshoot", std::move(reshoot));
}

void PodActions::create_maintenance_actions(ros::NodeHandle& nh) {
  using FormatServer = OperationServer<k40t_driver::FormatSdAction, ops::SdFormat>;
  FormatServer::Binding format;
  format.create = [](const k40t_driver::FormatSdGoal& goal, double now_s) {
    return ops::SdFormat::create(goal.timeout, now_s);
  };
  format.send = [this](const ops::SdFormat&, auto done) { send(p::FormatSdRequest{}, done); };
  format.feedback = [](const ops::SdFormat& op, k40t_driver::FormatSdFeedback& feedback) {
    feedback.status = op.tracker().status_text();
    feedback.reports = static_cast<uint32_t>(op.tracker().reports());
  };
  format.result = [](const ops::SdFormat&, k40t_driver::FormatSdResult&) {};
  format_ = std::make_unique<FormatServer>(nh, "format_sd", std::move(format));

  using UpgradeServer = OperationServer<k40t_driver::TfUpgradeAction, ops::TfUpgrade>;
  UpgradeServer::Binding upgrade;
  upgrade.create = [](const k40t_driver::TfUpgradeGoal& goal, double now_s) {
    return ops::TfUpgrade::create(goal.timeout, now_s);
  };
  upgrade.send = [this](const ops::TfUpgrade&, auto done) {
    send(p::TfCardUpgradeRequest{}, done);
  };
  upgrade.feedback = [](const ops::TfUpgrade& op, k40t_driver::TfUpgradeFeedback& feedback) {
    feedback.status = op.tracker().status_text();
    feedback.progress = static_cast<int8_t>(op.progress_percent());
  };
  upgrade.result = [](const ops::TfUpgrade&, k40t_driver::TfUpgradeResult&) {};
  upgrade_ = std::make_unique<UpgradeServer>(nh, "tf_upgrade", std::move(upgrade));
}

void PodActions::subscribe_status() {
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
