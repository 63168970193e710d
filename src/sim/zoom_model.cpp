#include "k40t_driver/sim/zoom_model.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/sim/lens.h"

namespace k40t::sim {

ZoomModel::ZoomModel(const ZoomConfig& config)
    : config_(config),
      zoom_(config.min_zoom),
      target_(config.min_zoom),
      focus_distance_m_(config.scene_distance_m) {}

void ZoomModel::reset() {
  zoom_ = target_ = config_.min_zoom;
  moving_ = announce_start_ = manual_focus_ = false;
  focus_left_s_ = 0;
  auto_focus_after_zoom_ = true;
  focus_area_.reset();
  focus_distance_m_ = config_.scene_distance_m;
}

void ZoomModel::start(double target) {
  focus_area_.reset();  // a zoom goes back to centre focus (3.2.4.18 note)
  target_ = std::clamp(target, config_.min_zoom, config_.max_zoom);
  if (!moving_) {
    moving_ = true;
    announce_start_ = true;  // "zooming" goes out at the next step, then every status period
  }
}

Outcome ZoomModel::set_zoom(double zoom) {
  if (!(zoom >= config_.min_zoom && zoom <= config_.max_zoom)) return Outcome::kFailure;
  start(zoom);
  return Outcome::kOk;
}

Outcome ZoomModel::zoom_control(ContinuousZoom command) {
  switch (command) {
    case ContinuousZoom::kIn:
      start(config_.max_zoom);
      break;
    case ContinuousZoom::kOut:
      start(config_.min_zoom);
      break;
    case ContinuousZoom::kStop:
      if (moving_) target_ = zoom_;  // the next step reports "done"
      break;
    case ContinuousZoom::kStepIn:
      start((moving_ ? target_ : zoom_) * config_.step_factor);
      break;
    case ContinuousZoom::kStepOut:
      start((moving_ ? target_ : zoom_) / config_.step_factor);
      break;
  }
  return Outcome::kOk;
}

Outcome ZoomModel::focus(FocusCommand command, const FocusArea& area) {
  constexpr int kStreamWidthPx = 1920;  // the corners are stream pixels (section 3.2.4.18)
  constexpr int kStreamHeightPx = 1080;
  // Auto focus runs for focus_time_s, on `on` or on the whole frame.
  const auto start_focus = [this](std::optional<FocusArea> on) {
    manual_focus_ = false;
    focus_left_s_ = config_.focus_time_s;
    focus_area_ = on;
    focus_distance_m_ = config_.scene_distance_m;
  };
  switch (command) {
    case FocusCommand::kArea:
      if (area.left < 0 || area.top < 0 || area.right <= area.left || area.bottom <= area.top ||
          area.right > kStreamWidthPx || area.bottom > kStreamHeightPx)
        return Outcome::kFailure;
      start_focus(area);
      break;
    case FocusCommand::kAuto:
    case FocusCommand::kOneTouch:
      start_focus(std::nullopt);
      break;
    case FocusCommand::kManualNear:
    case FocusCommand::kManualFar:
    case FocusCommand::kStopManual:
      manual_focus_ = command != FocusCommand::kStopManual;
      manual_nearer_ = command == FocusCommand::kManualNear;
      break;
    case FocusCommand::kAutoAfterZoomOn:
    case FocusCommand::kAutoAfterZoomOff:
      auto_focus_after_zoom_ = command == FocusCommand::kAutoAfterZoomOn;
      break;
  }
  return Outcome::kOk;
}

double ZoomModel::focal_length_mm() const {
  return sim::focal_length_mm(Lens::kTele, zoom_);
}

void ZoomModel::step(double dt_s, EventQueue& events) {
  if (focus_left_s_ > 0) focus_left_s_ = std::max(0.0, focus_left_s_ - dt_s);
  if (manual_focus_) {
    const double factor = std::exp2(dt_s / config_.manual_focus_halving_s);
    focus_distance_m_ =
        std::clamp(manual_nearer_ ? focus_distance_m_ / factor : focus_distance_m_ * factor,
                   config_.min_focus_m, config_.max_focus_m);
  }
  if (!moving_) return;
  if (announce_start_) {
    events.push_back(ZoomStatusEvent{true});
    announce_start_ = false;
    since_status_s_ = 0;
  }
  const double factor = std::exp2(dt_s / config_.doubling_time_s);
  zoom_ = target_ > zoom_ ? std::min(target_, zoom_ * factor) : std::max(target_, zoom_ / factor);
  if (zoom_ == target_) {
    moving_ = false;
    events.push_back(ZoomStatusEvent{false});
    if (auto_focus_after_zoom_) {
      focus_left_s_ = config_.focus_time_s;
      focus_distance_m_ = config_.scene_distance_m;
    }
    return;
  }
  since_status_s_ += dt_s;
  if (since_status_s_ >= config_.status_period_s) {
    since_status_s_ -= config_.status_period_s;
    events.push_back(ZoomStatusEvent{true});
  }
}

}  // namespace k40t::sim
