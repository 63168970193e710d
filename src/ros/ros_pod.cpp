#include "k40t_driver/ros/ros_pod.h"

#include <ros/console.h>

#include "k40t_driver/ros/stop_signals.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver {

namespace {

// One console line per change of the link's state (link_monitor.h): a warning for the states
// that need the user (cannot open, nothing answers, lost), information for the others.
void log_link_report(const PodLinkReport& report) {
  switch (report.state) {
    case PodLink::kCannotOpen:
    case PodLink::kNoAnswer:
    case PodLink::kLost:
      ROS_WARN("K40T %s", report.text.c_str());
      break;
    default:
      ROS_INFO("K40T %s", report.text.c_str());
      break;
  }
}

}  // namespace

Result<std::unique_ptr<RosPod>> RosPod::create(ros::NodeHandle nh, ros::NodeHandle private_nh) {
  Result<RosPodConfig> config = read_params(private_nh);
  if (!config) return Result<std::unique_ptr<RosPod>>::fail(config.error());
  Result<std::unique_ptr<PodDriver>> driver = PodDriver::create(
      config->driver, [] { return static_cast<StampNs>(ros::Time::now().toNSec()); });
  if (!driver) return Result<std::unique_ptr<RosPod>>::fail(driver.error());
  std::unique_ptr<RosPod> pod(
      new RosPod(nh, private_nh, config.value(), std::move(driver.value())));
  const Status started = pod->start();
  if (!started) return Result<std::unique_ptr<RosPod>>::fail(started.message());
  return pod;
}

RosPod::RosPod(ros::NodeHandle nh, ros::NodeHandle private_nh, const RosPodConfig& config,
               std::unique_ptr<PodDriver> driver)
    : config_(config), driver_(std::move(driver)) {
  // Every handler is registered before the link starts.
  topics_ = std::make_unique<TopicPublisher>(nh, *driver_, config_);
  if (config_.driver.replay) {
    replay_ = subscribe_replay_input(nh, *driver_);
  } else {
    settings_ = std::make_unique<SettingsSync>(private_nh, *driver_);
    commands_ = std::make_unique<CommandInput>(nh, *driver_);
    // Each action server's goal thread is created with it: named for `top -H`.
    const transport::ThreadNameScope goal_threads("k40t_goal");
    actions_ = std::make_unique<PodActions>(nh, *driver_);
  }
  diagnostics_ =
      std::make_unique<PodDiagnostics>(nh, private_nh, *driver_, config_, settings_.get());
  locator_ = std::make_unique<TargetLocator>(nh, private_nh, *driver_, config_, *diagnostics_);
  if (!config_.driver.replay) {
    const transport::ThreadNameScope look_at_thread("k40t_look_at");
    look_at_ = std::make_unique<LookAtServer>(nh, private_nh, *driver_, config_, locator_->tf());
  }
  services_ = std::make_unique<PodServices>(nh, *driver_);
  settings_services_ = std::make_unique<SettingsServices>(nh, settings_.get());
  job_services_ = std::make_unique<JobServices>(nh, *driver_);
  driver_->on_pod_online([this] { on_pod_online(); });
  driver_->set_shutdown_query([] { return shutdown_requested(); });
  driver_->on_link_report(log_link_report);
}

RosPod::~RosPod() {
  // Running goals end and their threads are joined while the link still runs (they may be
  // waiting for it); then the link stops so that no handler runs into a half-destroyed glue
  // object.
  if (actions_) actions_->shutdown();
  if (look_at_) look_at_->shutdown();
  if (driver_) driver_->stop();
}

Status RosPod::start() {
  // Before the link's own lines (waiting, connected...), which the I/O thread logs at once.
  if (!config_.driver.replay) {
    ROS_INFO("K40T driver starting on %s",
             device_url_with_baud(config_.driver.device, config_.driver.baud).c_str());
  }
  const Status started = driver_->start();
  if (started && actions_) actions_->start();  // goals are taken once the link runs
  if (started && look_at_) look_at_->start();
  return started;
}

void RosPod::on_pod_online() {
  ROS_INFO("K40T pod online: reading versions and settings");
  const PodVersions versions = read_versions(*driver_);
  diagnostics_->set_versions(versions);
  if (!versions.ok) ROS_WARN("K40T versions not read: %s", versions.message.c_str());
  if (settings_) settings_->read_from_pod();
}

}  // namespace k40t::driver
