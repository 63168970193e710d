#include "k40t_driver/sim/gimbal_model.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/sim/geometry.h"

namespace k40t::sim {

namespace {
constexpr double kImageWidthPx = 1920;   // 0x00002C coordinates: 1..1920, centre 960
constexpr double kImageHeightPx = 1080;  // 1..1080, centre 540
bool inside_image(double x_px, double y_px) {
  return x_px >= 1 && x_px <= kImageWidthPx && y_px >= 1 && y_px <= kImageHeightPx;
}
}  // namespace

void GimbalModel::Axis::aim(double where) {
  target = wraps ? wrap_deg(where) : std::clamp(where, min, max);
  drive = Drive::kToTarget;
}

double GimbalModel::Axis::advance(double dt_s) {
  const double before = angle;
  const double step = speed * dt_s;
  switch (drive) {
    case Drive::kHold:
      break;
    case Drive::kToTarget: {
      // A continuous joint turns the short way (through +-180 when that is shorter).
      const double to_go = wraps ? wrap_deg(target - angle) : target - angle;
      if (std::abs(to_go) <= step) {
        angle = target;
        drive = Drive::kHold;
      } else {
        angle += to_go > 0 ? step : -step;
        if (wraps) angle = wrap_deg(angle);
      }
      break;
    }
    case Drive::kNegative:
    case Drive::kPositive:
      if (wraps) {
        angle = wrap_deg(angle + (drive == Drive::kPositive ? step : -step));
        target = angle;
        break;
      }
      angle = std::clamp(angle + (drive == Drive::kPositive ? step : -step), min, max);
      target = angle;
      if (angle == min || angle == max) drive = Drive::kHold;  // at the end stop
      break;
  }
  const double moved = wraps ? wrap_deg(angle - before) : angle - before;
  return dt_s > 0 ? moved / dt_s : 0.0;
}

GimbalModel::GimbalModel(const GimbalConfig& config) : config_(config) {
  yaw_.min = config.yaw_min_deg;
  yaw_.max = config.yaw_max_deg;
  yaw_.wraps = config.yaw_continuous;
  pitch_.min = config.pitch_min_deg;
  pitch_.max = config.pitch_max_deg;
  yaw_.speed = pitch_.speed = config.default_dial_speed_deg_s;
}

Outcome GimbalModel::ready_to_move() {
  if (calibration_ || restarting() || tracking_) return Outcome::kBusy;
  servo_on_ = true;
  return Outcome::kOk;
}

Outcome GimbalModel::set_dial_speed(double pitch_deg_s, double yaw_deg_s) {
  const auto in_range = [&](double v) {
    return v >= config_.min_dial_speed_deg_s && v <= config_.max_dial_speed_deg_s;
  };
  if (!in_range(pitch_deg_s) || !in_range(yaw_deg_s)) return Outcome::kFailure;
  pitch_.speed = pitch_deg_s;
  yaw_.speed = yaw_deg_s;
  return Outcome::kOk;
}

Outcome GimbalModel::command_angles(std::optional<double> pitch_deg,
                                    std::optional<double> yaw_deg) {
  if (pitch_deg && (*pitch_deg < pitch_.min || *pitch_deg > pitch_.max)) return Outcome::kFailure;
  if (yaw_deg && (*yaw_deg < yaw_.min || *yaw_deg > yaw_.max)) return Outcome::kFailure;
  const Outcome ready = ready_to_move();
  if (ready != Outcome::kOk) return ready;
  if (pitch_deg) pitch_.aim(*pitch_deg);
  if (yaw_deg) yaw_.aim(*yaw_deg);
  return Outcome::kOk;
}

void GimbalModel::set_motion(Axis& axis, bool negative, bool positive) {
  if (negative) {
    axis.drive = Drive::kNegative;
  } else if (positive) {
    axis.drive = Drive::kPositive;
  } else {
    axis.drive = Drive::kHold;
    axis.target = axis.angle;
  }
}

Outcome GimbalModel::move(YawMotion yaw, PitchMotion pitch) {
  const Outcome ready = ready_to_move();
  if (ready != Outcome::kOk) return ready;
  set_motion(yaw_, yaw == YawMotion::kLeft, yaw == YawMotion::kRight);
  set_motion(pitch_, pitch == PitchMotion::kDown, pitch == PitchMotion::kUp);
  return Outcome::kOk;
}

Outcome GimbalModel::centre() {
  return command_angles(0.0, 0.0);
}
Outcome GimbalModel::look_down() {
  return command_angles(config_.pitch_min_deg, 0.0);
}

Outcome GimbalModel::point_at(Lens lens, double zoom, double x_px, double y_px) {
  if (!inside_image(x_px, y_px)) return Outcome::kFailure;
  const Outcome ready = ready_to_move();
  if (ready != Outcome::kOk) return ready;
  return aim_at_pixel(lens, zoom, x_px, y_px);
}

Outcome GimbalModel::start_tracking(Lens lens, double zoom, double x_px, double y_px) {
  if (calibration_ || restarting()) return Outcome::kBusy;
  tracking_ = false;
  const Outcome aimed = aim_at_pixel(lens, zoom, x_px, y_px);
  if (aimed != Outcome::kOk) return aimed;
  servo_on_ = true;
  tracking_ = true;
  return Outcome::kOk;
}

Outcome GimbalModel::aim_at_pixel(Lens lens, double zoom, double x_px, double y_px) {
  if (!inside_image(x_px, y_px)) return Outcome::kFailure;
  const FieldOfView fov = field_of_view(lens, zoom);
  // The ray through the pixel, from where the camera looks now (targets, if still moving, would
  // be wrong: the user clicked on the image as it is).
  const CameraBasis basis = camera_basis(yaw_.angle, pitch_.angle);
  const double nx = (x_px - kImageWidthPx / 2) / (kImageWidthPx / 2) *
                    std::tan(deg_to_rad(fov.horizontal_deg / 2));
  const double ny = -(y_px - kImageHeightPx / 2) / (kImageHeightPx / 2) *
                    std::tan(deg_to_rad(fov.vertical_deg / 2));
  const Vec3 ray = basis.forward + basis.right * nx + basis.up * ny;
  const double yaw = yaw_.angle + wrap_deg(yaw_of(ray) - yaw_.angle);
  servo_on_ = true;
  yaw_.aim(yaw);
  pitch_.aim(pitch_of(ray));
  return Outcome::kOk;
}

Outcome GimbalModel::servo_off() {
  if (calibration_) return Outcome::kBusy;
  servo_on_ = false;
  set_motion(yaw_, false, false);
  set_motion(pitch_, false, false);
  return Outcome::kOk;
}

Outcome GimbalModel::set_stabilisation(bool on) {
  stabilisation_enabled_ = on;
  return Outcome::kOk;
}

StabilisationState GimbalModel::stabilisation_state() const {
  if (!stabilisation_enabled_ || !servo_on_ || restarting()) return StabilisationState::kOff;
  return StabilisationState::kActive;
}

Outcome GimbalModel::start_calibration(CalibrationKind kind) {
  if (calibration_ || restarting()) return Outcome::kBusy;
  Calibration calibration;
  switch (kind) {
    case CalibrationKind::kDrift:
      calibration.duration_s = config_.drift_calibration_s;
      break;
    case CalibrationKind::kLinear:
      calibration.duration_s = config_.linear_calibration_s;
      break;
    case CalibrationKind::kAccelerometer:
      calibration.duration_s = config_.accelerometer_calibration_s;
      break;
  }
  calibration_ = calibration;
  // The gimbal holds still while it calibrates.
  set_motion(yaw_, false, false);
  set_motion(pitch_, false, false);
  return Outcome::kOk;
}

std::optional<double> GimbalModel::calibration_progress() const {
  if (!calibration_) return std::nullopt;
  return std::min(1.0, calibration_->elapsed_s / calibration_->duration_s);
}

Outcome GimbalModel::soft_restart() {
  if (calibration_) return Outcome::kBusy;
  restart_left_s_ = config_.restart_s;
  servo_on_ = false;
  set_motion(yaw_, false, false);
  set_motion(pitch_, false, false);
  return Outcome::kOk;
}

void GimbalModel::step(double dt_s, EventQueue& events) {
  if (restart_left_s_ > 0) {
    restart_left_s_ -= dt_s;
    if (restart_left_s_ <= 0) {
      restart_left_s_ = 0;
      servo_on_ = true;
      yaw_.aim(0);
      pitch_.aim(0);
    }
  }
  if (calibration_) {
    Calibration& c = *calibration_;
    c.elapsed_s += dt_s;
    while (c.elapsed_s >= c.next_report_s && c.next_report_s < c.duration_s) {
      const double fraction = c.next_report_s / c.duration_s;
      events.push_back(MaintenanceEvent{MaintenanceState::kRepairing,
                                        static_cast<uint8_t>(std::lround(fraction * 100)), true});
      c.next_report_s += 1.0;
    }
    if (c.elapsed_s >= c.duration_s) {
      events.push_back(MaintenanceEvent{MaintenanceState::kSucceeded, 100, true});
      calibration_.reset();
    }
  }
  const bool driven = servo_on_;
  pose_.rate_deg_s.yaw = driven ? yaw_.advance(dt_s) : 0.0;
  pose_.rate_deg_s.pitch = driven ? pitch_.advance(dt_s) : 0.0;
  pose_.rate_deg_s.roll = 0;
  pose_.joint_deg = {yaw_.angle, pitch_.angle, config_.roll_deg};
}

}  // namespace k40t::sim
