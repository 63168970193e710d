#include "k40t_driver/driver/look_at_controller.h"

#include <algorithm>
#include <cmath>

namespace k40t::driver {

namespace {
constexpr double kMaxRateGapS = 0.5;  // steps further apart than this restart the rate estimate
}

void LookAtController::reset() {
  history_.clear();
  rate_ = {};
  sent_.reset();
  commanded_rate_ = {};
}

void LookAtController::update_rate(double now_s, const geo::GimbalAim& desired) {
  if (!history_.empty() && now_s <= history_.back().t_s) return;  // nothing newer
  if (!history_.empty() && now_s - history_.back().t_s > kMaxRateGapS) history_.clear();
  history_.push_back({now_s, desired});
  while (history_.size() > 2 && now_s - history_[1].t_s >= config_.rate_window_s)
    history_.pop_front();  // keep the newest sample at least a window back
  const Sample& oldest = history_.front();
  const double dt = now_s - oldest.t_s;
  if (dt < config_.rate_window_s) return;  // too short to tell: the last estimate stands
  // The target's own motion: always the short way, whatever the joint can do.
  rate_.yaw_deg = geo::wrap_deg(desired.yaw_deg - oldest.aim.yaw_deg) / dt;
  rate_.pitch_deg = (desired.pitch_deg - oldest.aim.pitch_deg) / dt;
}

LookAtStep LookAtController::step(double now_s, const geo::Vector3& target,
                                  const std::optional<geo::GimbalAim>& joints, double joints_s,
                                  double target_age_s) {
  LookAtStep out;
  const Result<geo::GimbalAim> aim = geo::aim_along(target);
  if (!aim) {
    out.reach = Status::fail(aim.error());
    return out;
  }
  out.desired = aim.value();
  out.reach = geo::check_reach(out.desired, config_.limits);
  out.error_deg = joints ? geo::pointing_error_deg(*joints, target) : std::nan("");
  if (!out.reach) return out;
  const double age = std::clamp(target_age_s, 0.0, kMaxRateGapS);
  update_rate(now_s - age, out.desired);
  const double lead = config_.lead_s + age;

  const geo::GimbalLimits& limits = config_.limits;
  geo::GimbalAim predicted;
  predicted.yaw_deg = out.desired.yaw_deg + rate_.yaw_deg * lead;
  predicted.yaw_deg = limits.yaw_continuous
                          ? geo::wrap_deg(predicted.yaw_deg)
                          : std::clamp(predicted.yaw_deg, limits.yaw_min_deg, limits.yaw_max_deg);
  predicted.pitch_deg = std::clamp(out.desired.pitch_deg + rate_.pitch_deg * lead,
                                   limits.pitch_min_deg, limits.pitch_max_deg);
  if (config_.drive == LookAtDrive::kAngle) {
    out.angle = angle_command(predicted);
  } else if (joints) {  // no report yet: nothing to close the loop on, nothing commanded
    const double joints_age = std::clamp(now_s - joints_s, 0.0, kMaxRateGapS);
    geo::GimbalAim now{joints->yaw_deg + commanded_rate_.yaw_deg * joints_age,
                       joints->pitch_deg + commanded_rate_.pitch_deg * joints_age};
    if (limits.yaw_continuous) now.yaw_deg = geo::wrap_deg(now.yaw_deg);
    out.rate = rate_command(predicted, now);
  }
  return out;
}

std::optional<geo::GimbalAim> LookAtController::angle_command(const geo::GimbalAim& predicted) {
  if (sent_ &&
      std::abs(geo::wrap_deg(predicted.yaw_deg - sent_->yaw_deg)) < config_.min_change_deg &&
      std::abs(predicted.pitch_deg - sent_->pitch_deg) < config_.min_change_deg)
    return std::nullopt;
  sent_ = predicted;
  return predicted;
}

geo::GimbalAim LookAtController::rate_command(const geo::GimbalAim& predicted,
                                              const geo::GimbalAim& joints) {
  geo::GimbalAim rate;
  const double yaw_error = geo::yaw_turn_deg(joints.yaw_deg, predicted.yaw_deg, config_.limits);
  const double pitch_error = predicted.pitch_deg - joints.pitch_deg;
  const double max = config_.max_rate_deg_s;
  rate.yaw_deg = std::clamp(rate_.yaw_deg + config_.rate_gain * yaw_error, -max, max);
  rate.pitch_deg = std::clamp(rate_.pitch_deg + config_.rate_gain * pitch_error, -max, max);
  commanded_rate_ = rate;
  return rate;
}

std::optional<double> FootprintZoom::step(double slant_m) {
  if (!std::isfinite(slant_m) || slant_m <= 0) return std::nullopt;
  double zoom = geo::footprint_zoom(slant_m, width_m_, tan_half_fov_1x_, kMinZoom, kMaxZoom);
  zoom = std::round(zoom * 10.0) / 10.0;  // 0x000304's 0.1 steps
  if (asked_ && std::abs(zoom - *asked_) <= hysteresis_ * *asked_) return std::nullopt;
  asked_ = zoom;
  return zoom;
}

}  // namespace k40t::driver
