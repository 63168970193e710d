#include "k40t_driver/ros/look_at_server.h"

#include <algorithm>
#include <cmath>

#include <ros/console.h>

#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver {

namespace {

using k40t_driver::LookAtGoal;
constexpr double kDegToRad = M_PI / 180.0;
// The tele's nominal optics (docs/video.md): 5.6 mm wide behind 4.7 mm at 1x.
constexpr double kTeleHalfWidthMm = 2.8;
constexpr double kTeleFocalMm = 4.7;

}  // namespace

LookAtServer::LookAtServer(ros::NodeHandle nh, const ros::NodeHandle& private_nh, PodDriver& driver,
                           const RosPodConfig& config, const tf2_ros::Buffer& tf)
    : driver_(driver),
      resolver_(tf, driver, config.ids.base,
                private_nh.param<std::string>("vehicle_frame", config.ids.base)),
      server_(nh, "gimbal/look_at", false) {
  config_ = config.look_at.control;
  period_s_ = 1.0 / config.look_at.rate_hz;
  point_timeout_s_ = config.look_at.point_timeout_s;
  tan_half_fov_1x_ = kTeleHalfWidthMm / kTeleFocalMm;

  driver.on<protocol::GimbalAttitude>([this](const protocol::GimbalAttitude& m, StampNs stamp) {
    std::lock_guard<std::mutex> lock(mutex_);
    joints_ = geo::GimbalAim{m.joint_yaw_deg, m.joint_pitch_deg};
    joints_s_ = static_cast<double>(stamp) * 1e-9;
  });
  driver.on<protocol::VisibleStatus>([this](const protocol::VisibleStatus& m, StampNs) {
    std::lock_guard<std::mutex> lock(mutex_);
    zoom_ = m.zoom_x;
  });
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  point_sub_ = nh.subscribe("gimbal/look_at_point", 1, &LookAtServer::on_point, this, hints);
  camera_info_sub_ = nh.subscribe<sensor_msgs::CameraInfo>(
      "camera_info", 1, [this](const sensor_msgs::CameraInfo::ConstPtr& info) {
        std::lock_guard<std::mutex> lock(mutex_);
        camera_info_ = *info;
      });
  marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("gimbal/look_at_marker", 1, true);
  // Both run under the action server's lock: they only hand over and wake the thread.
  server_.registerGoalCallback([this] { on_goal(); });
  server_.registerPreemptCallback([this] { on_preempt(); });
  thread_ = std::thread([this] { run(); });
}

LookAtServer::~LookAtServer() {
  shutdown();
}

void LookAtServer::start() {
  server_.start();
}

void LookAtServer::shutdown() {
  if (shut_down_.exchange(true)) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wakeup_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void LookAtServer::on_goal() {
  const k40t_driver::LookAtGoalConstPtr goal = server_.acceptNewGoal();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_goal_ = goal;
    preempt_ = false;  // a replaced goal was ended by acceptNewGoal
  }
  wakeup_.notify_one();
}

void LookAtServer::on_preempt() {
  if (server_.isNewGoalAvailable()) return;  // replaced: on_goal follows
  {
    std::lock_guard<std::mutex> lock(mutex_);
    preempt_ = true;
  }
  wakeup_.notify_one();
}

void LookAtServer::on_point(const geometry_msgs::PointStamped::ConstPtr& msg) {
  const Result<LookAtTarget> target = target_of_point(*msg);
  if (!target) {
    ROS_WARN_THROTTLE(1.0, "gimbal/look_at_point ignored: %s", target.error().c_str());
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_point_ = *msg;
    latest_point_time_ = ros::Time::now();
  }
  wakeup_.notify_one();
}

void LookAtServer::run() {
  using Clock = std::chrono::steady_clock;
  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_s_));
  Clock::time_point next_step = Clock::now();
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (stopping_) break;
      // Steps keep their period while something is followed (a point does not bring the next
      // one forward: the rate estimate and the pod's load want a steady pace); a goal, a cancel
      // or the first point is served at once.
      const auto urgent = [this] { return stopping_ || pending_goal_ || preempt_; };
      if (session_) {
        wakeup_.wait_until(lock, next_step, urgent);
      } else if (latest_point_) {
        wakeup_.wait_for(lock, period, urgent);  // a stale point is dropped by update_session
      } else {
        wakeup_.wait(lock, [this] { return stopping_ || pending_goal_ || latest_point_; });
      }
      if (stopping_) break;
    }
    next_step = std::max(next_step + period, Clock::now());
    const ros::Time now = ros::Time::now();
    Following* f = update_session(now);
    if (f && !step(*f, now)) session_.reset();
  }
  if (session_) {
    stop_gimbal();  // nothing follows any more: the gimbal must not keep turning
    end(*session_, false, "the driver is shutting down; the gimbal stopped");
  }
  session_.reset();
  if (server_.isActive()) server_.setAborted(k40t_driver::LookAtResult(), "shutting down");
}

std::optional<std::string> LookAtServer::configure(Following& f, const LookAtGoal& goal) const {
  const Result<LookAtTarget> target = target_of_goal(goal);
  if (!target) return target.error();
  f.target = target.value();
  f.from_goal = true;
  f.follow = goal.follow;
  if (goal.lens > LookAtGoal::LENS_THERMAL)
    return "lens must be LENS_TELE, LENS_WIDE or LENS_THERMAL";
  f.zoom_policy = goal.zoom_policy;
  switch (goal.zoom_policy) {
    case LookAtGoal::ZOOM_LEAVE:
      break;
    case LookAtGoal::ZOOM_FIXED:
      if (!(goal.zoom_ratio >= protocol::kMinZoomRatio &&
            goal.zoom_ratio <= protocol::kMaxZoomRatio))
        return "zoom_ratio must be 1.0 .. 160.0";
      f.zoom_ratio = goal.zoom_ratio;
      break;
    case LookAtGoal::ZOOM_FOOTPRINT:
      if (!(std::isfinite(goal.footprint_width) && goal.footprint_width > 0))
        return "footprint_width must be a positive number of metres";
      if (goal.lens != LookAtGoal::LENS_TELE)
        return "ZOOM_FOOTPRINT drives the tele's hybrid zoom (0x000304): use LENS_TELE";
      f.footprint.emplace(goal.footprint_width, tan_half_fov_1x_);
      break;
    default:
      return "zoom_policy must be ZOOM_LEAVE, ZOOM_FIXED or ZOOM_FOOTPRINT";
  }
  LookAtConfig config = config_;
  if (goal.max_rate != 0) {
    const double deg_s = goal.max_rate / kDegToRad;
    if (!(deg_s >= protocol::GimbalDialSpeedRequest::kMinDegS - 1e-6 &&
          deg_s <= protocol::GimbalDialSpeedRequest::kMaxDegS + 1e-6))
      return "max_rate must be 0.0175 .. 0.5236 rad/s (the dial speed's 1 .. 30 deg/s), or 0";
    config.max_rate_deg_s = std::clamp(deg_s, protocol::GimbalDialSpeedRequest::kMinDegS,
                                       protocol::GimbalDialSpeedRequest::kMaxDegS);
  }
  f.controller = LookAtController(config);
  const double tolerance = goal.tolerance == 0 ? LookAtGoal::DEFAULT_TOLERANCE : goal.tolerance;
  if (!(std::isfinite(tolerance) && tolerance > 0)) return "tolerance must be positive (rad), or 0";
  f.tolerance_deg = tolerance / kDegToRad;
  const double timeout = goal.timeout == 0 ? LookAtGoal::DEFAULT_TIMEOUT : goal.timeout;
  if (!(std::isfinite(timeout) && timeout > 0)) return "timeout must be positive (s), or 0";
  f.start = ros::Time::now();
  if (!goal.follow) f.deadline = f.start + ros::Duration(timeout);
  return std::nullopt;
}

LookAtServer::Following* LookAtServer::update_session(const ros::Time& now) {
  k40t_driver::LookAtGoalConstPtr goal;
  bool preempt = false;
  std::optional<geometry_msgs::PointStamped> point;
  ros::Time point_time;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    goal.swap(pending_goal_);
    std::swap(preempt, preempt_);
    point = latest_point_;
    point_time = latest_point_time_;
  }
  if (goal) {  // a goal replaces whatever was followed (actionlib ended a replaced goal)
    const bool was_following = session_ != nullptr;
    session_ = std::make_unique<Following>(config_);
    if (const std::optional<std::string> refused = configure(*session_, *goal)) {
      session_.reset();
      if (was_following) {  // what it replaced ended: the gimbal must not go on turning
        stop_gimbal();
        marker_pub_.publish(clear_look_at_markers(resolver_.base_frame()));
      }
      k40t_driver::LookAtResult result;
      result.message = *refused;
      result.error = result.slant_range = std::nan("");
      server_.setAborted(result, result.message);
      return nullptr;
    }
    begin(*session_);
  } else if (preempt && session_ && session_->from_goal) {
    stop_gimbal();
    end(*session_, false, "cancelled: the gimbal stopped where it was", true);
    session_.reset();
    return nullptr;
  }
  if (session_ && session_->from_goal) return session_.get();

  // gimbal/look_at_point: the latest point while they keep coming.
  const bool fresh = point && (now - point_time).toSec() <= point_timeout_s_;
  if (!fresh) {
    if (session_) {
      stop_gimbal();
      end(*session_, false, "");
      ROS_INFO("gimbal/look_at_point: no point for %.1f s: stopped following", point_timeout_s_);
      session_.reset();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (latest_point_ && latest_point_time_ == point_time) latest_point_.reset();
    return nullptr;
  }
  if (!session_) {
    session_ = std::make_unique<Following>(config_);
    session_->start = now;
    begin(*session_);
  }
  session_->target = target_of_point(*point).value();
  return session_.get();
}

void LookAtServer::begin(Following& f) {
  angle_in_flight_ = false;
  if (f.controller.config().drive == LookAtDrive::kAngle) {
    // Angle commands turn at the dial speed: the goal's maximum rate.
    protocol::GimbalDialSpeedRequest speed;
    speed.pitch_speed_deg_s = speed.yaw_speed_deg_s = f.controller.config().max_rate_deg_s;
    driver_.request_async(speed, [](const session::AckResult& ack) {
      if (!ack.ok()) ROS_WARN("gimbal/look_at: dial speed not set: %s", ack.message.c_str());
    });
  }
  if (f.zoom_policy == LookAtGoal::ZOOM_FIXED) {
    protocol::ZoomRatioRequest zoom;
    zoom.zoom_x = f.zoom_ratio;
    driver_.request_async(zoom, [](const session::AckResult& ack) {
      if (!ack.ok()) ROS_WARN("gimbal/look_at: zoom not set: %s", ack.message.c_str());
    });
  }
}
}  // namespace k40t::driver
