// LookAtServer's control step (look_at_server.h): resolve, step, send, zoom, feedback, end.
#include <cmath>

#include <ros/console.h>

#include "k40t_driver/camera/pixel_ray.h"
#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/ros/camera_views.h"
#include "k40t_driver/ros/look_at_server.h"

namespace k40t::driver {

namespace {
using k40t_driver::LookAtGoal;
constexpr double kDegToRad = M_PI / 180.0;
constexpr int kSettledSteps = 3;  // consecutive steps within the tolerance settle a goal

double norm(const geo::Vector3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}
}  // namespace

bool LookAtServer::step(Following& f, const ros::Time& now) {
  const Result<TargetInBase> where = resolver_.resolve(f.target, now);
  if (!where) {
    if (f.from_goal) {
      stop_gimbal();
      end(f, false, "target not located: " + where.error());
      return false;
    }
    ROS_WARN_THROTTLE(1.0, "gimbal/look_at_point: %s", where.error().c_str());
    return true;
  }
  std::optional<geo::GimbalAim> joints;
  double joints_s = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    joints = joints_;
    joints_s = joints_s_;
  }
  const LookAtStep s =
      f.controller.step(now.toSec(), where->vector, joints, joints_s, where->age_s);
  if (!s.reach) {
    stop_gimbal();
    if (!f.from_goal) {
      ROS_WARN_THROTTLE(1.0, "gimbal/look_at_point: %s", s.reach.message().c_str());
      std::lock_guard<std::mutex> lock(mutex_);
      latest_point_.reset();  // refused: wait for the next point
    }
    end(f, false, s.reach.message());
    return false;
  }
  if (s.angle) {
    if (angle_in_flight_.exchange(true)) {
      f.controller.forget_sent();  // the last one is still on its way: send again next step
    } else {
      protocol::GimbalAngleRequest request;
      request.pitch_deg = s.angle->pitch_deg;
      request.yaw_deg = s.angle->yaw_deg;
      driver_.request_async(request, [this](const session::AckResult& ack) {
        angle_in_flight_ = false;
        if (!ack.ok())
          ROS_WARN_THROTTLE(1.0, "gimbal/look_at: angle refused: %s", ack.message.c_str());
      });
    }
  }
  if (s.rate) driver_.command_rate(s.rate->pitch_deg, s.rate->yaw_deg);
  const double slant = norm(where->vector);
  apply_zoom(f, slant);
  f.last_error_deg = s.error_deg;
  f.last_slant_m = slant;
  marker_pub_.publish(look_at_markers(resolver_.base_frame(), now, where->vector, joints));
  if (!f.from_goal) return true;
  publish_feedback(f, s, slant, where->vector, now);
  if (f.follow) return true;
  f.settled = s.error_deg <= f.tolerance_deg ? f.settled + 1 : 0;
  if (f.settled >= kSettledSteps) {
    end(f, true, "settled within the tolerance");
    return false;
  }
  if (now > f.deadline) {
    stop_gimbal();
    end(f, false, "timed out before settling; the gimbal stopped");
    return false;
  }
  return true;
}

void LookAtServer::apply_zoom(Following& f, double slant_m) {
  if (!f.footprint) return;
  const std::optional<double> zoom = f.footprint->step(slant_m);
  if (!zoom) return;
  protocol::ZoomRatioRequest request;
  request.zoom_x = *zoom;
  driver_.request_async(request, [](const session::AckResult& ack) {
    if (!ack.ok()) ROS_WARN_THROTTLE(1.0, "gimbal/look_at: zoom refused: %s", ack.message.c_str());
  });
}

void LookAtServer::publish_feedback(Following& f, const LookAtStep& s, double slant_m,
                                    const geo::Vector3& target, const ros::Time& now) {
  k40t_driver::LookAtFeedback feedback;
  feedback.error = s.error_deg;
  feedback.slant_range = slant_m;
  feedback.pitch = -s.desired.pitch_deg * kDegToRad;  // REP 103: down positive
  feedback.yaw = -s.desired.yaw_deg * kDegToRad;      // left positive
  feedback.elapsed = (now - f.start).toSec();
  feedback.u = feedback.v = std::nan("");
  std::optional<sensor_msgs::CameraInfo> info;
  std::optional<geo::GimbalAim> joints;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    info = camera_info_;
    joints = joints_;
    feedback.zoom = zoom_;
  }
  feedback.footprint_width = geo::footprint_width_m(slant_m, feedback.zoom, tan_half_fov_1x_);
  if (info && info->K[0] > 0) {
    // Where the camera looks now: the reported joints (the target's own angles before a report).
    const geo::Vector3 optical = geo::in_optical_frame(joints.value_or(s.desired), target);
    const Result<std::array<double, 2>> pixel =
        optical[2] > 0 ? camera::project_ray(camera_model(*info), optical)
                       : Result<std::array<double, 2>>::fail("behind the camera");
    if (pixel) {
      feedback.u = (*pixel)[0];
      feedback.v = (*pixel)[1];
      feedback.in_image = feedback.u >= 0 && feedback.v >= 0 && feedback.u < info->width &&
                          feedback.v < info->height;
    }
  }
  server_.publishFeedback(feedback);
}

void LookAtServer::end(Following& f, bool success, const std::string& message, bool preempted) {
  marker_pub_.publish(clear_look_at_markers(resolver_.base_frame()));
  if (!f.from_goal) return;
  k40t_driver::LookAtResult result;
  result.success = success;
  result.message = message;
  result.error = f.last_error_deg;
  result.slant_range = f.last_slant_m;
  result.elapsed = (ros::Time::now() - f.start).toSec();
  if (success) {
    server_.setSucceeded(result, message);
  } else if (preempted) {
    server_.setPreempted(result, message);
  } else {
    server_.setAborted(result, message);
  }
}

void LookAtServer::stop_gimbal() {
  if (config_.drive == LookAtDrive::kRate) {
    driver_.command_rate(0, 0);
    return;
  }
  driver_.request_async(protocol::GimbalControlRequest{}, [](const session::AckResult& ack) {
    if (!ack.ok()) ROS_WARN("gimbal/look_at: stop refused: %s", ack.message.c_str());
  });
}

}  // namespace k40t::driver
