#include "k40t_driver/operations/camera_operations.h"

#include <cmath>

namespace k40t::operations {

namespace p = protocol;

namespace {

Step step(Phase phase, std::string text) {
  Step s;
  s.phase = phase;
  s.text = std::move(text);
  return s;
}

// The enum's own text, or the code for one the document does not define.
template <class E>
std::string state_text(E state) {
  const char* text = to_string(state);
  return text ? text : "state " + std::to_string(static_cast<int>(state));
}

}  // namespace

Step zoom_step(const p::ZoomStatus& status) {
  return status.progress == p::ZoomProgress::kDone ? step(Phase::kSucceeded, "done")
                                                   : step(Phase::kRunning, "zooming");
}

Step sd_format_step(const p::SdFormatStatus& status) {
  switch (status.state) {
    case p::SdFormatState::kDone:
      return step(Phase::kSucceeded, state_text(status.state));
    case p::SdFormatState::kFormatting:
      return step(Phase::kRunning, state_text(status.state));
    case p::SdFormatState::kFailed:
    case p::SdFormatState::kUnavailable:
      break;
  }
  return step(Phase::kFailed, state_text(status.state));
}

Step reshoot_step(const p::PreciseReshootStatus& status) {
  switch (status.state) {
    case p::ReshootState::kDone:
      return step(Phase::kSucceeded, state_text(status.state));
    case p::ReshootState::kReshooting:
    case p::ReshootState::kBurst:
    case p::ReshootState::kContinuous:
    case p::ReshootState::kTimeLapse:
    case p::ReshootState::kSingleShot:
      return step(Phase::kRunning, state_text(status.state));
    default:  // stopped, failed, and the SD card states 7..11
      return step(Phase::kFailed, state_text(status.state));
  }
}

Step tf_upgrade_step(const p::TfCardUpgradeStatus& status) {
  switch (status.state) {
    case p::TfUpgradeState::kSucceeded:
      return step(Phase::kSucceeded, state_text(status.state));
    case p::TfUpgradeState::kUpgrading:
      return step(Phase::kRunning, state_text(status.state));
    case p::TfUpgradeState::kFailed:
      break;
  }
  return step(Phase::kFailed, state_text(status.state));
}

// ---- zoom ------------------------------------------------------------------------------------

Result<ZoomTo> ZoomTo::create(double ratio_x, double timeout_s, double now_s) {
  // Named as the goal names it; the struct's own check stays as the backstop.
  const Status in_range = p::check_range("ratio", ratio_x, p::kMinZoomRatio, p::kMaxZoomRatio, "x");
  if (!in_range) return in_range;
  p::ZoomRatioRequest request;
  request.zoom_x = ratio_x;
  const Status valid = request.validate();
  if (!valid) return valid;
  const TimeoutChoice timeout = choose_timeout(timeout_s, kDefaultTimeoutS);
  if (!timeout.ok) return Status::fail(timeout.error);
  return ZoomTo(request, timeout.seconds, now_s);
}

ZoomTo::ZoomTo(const p::ZoomRatioRequest& request, double timeout_s, double now_s)
    : request_(request), tracker_("zoom", "zoom status 0x020304 'done'", timeout_s, now_s) {}

// ---- SD format -------------------------------------------------------------------------------

Result<SdFormat> SdFormat::create(double timeout_s, double now_s) {
  const TimeoutChoice timeout = choose_timeout(timeout_s, kDefaultTimeoutS);
  if (!timeout.ok) return Status::fail(timeout.error);
  return SdFormat(timeout.seconds, now_s);
}

SdFormat::SdFormat(double timeout_s, double now_s)
    : tracker_("SD format", "SD format status 0x02030D 'done'", timeout_s, now_s) {}

// ---- precise re-shoot ------------------------------------------------------------------------

Result<p::ReshootResolution> reshoot_resolution(uint16_t width_px, uint16_t height_px) {
  struct Size {
    uint16_t width, height;
    p::ReshootResolution code;
  };
  static constexpr Size kSizes[] = {{8000, 6000, p::ReshootResolution::k8000x6000},
                                    {4000, 3000, p::ReshootResolution::k4000x3000},
                                    {5160, 3890, p::ReshootResolution::k5160x3890},
                                    {5664, 4248, p::ReshootResolution::k5664x4248}};
  if (width_px == 0 && height_px == 0) return p::ReshootResolution::k4000x3000;
  for (const Size& size : kSizes) {
    if (size.width == width_px && size.height == height_px) return size.code;
  }
  return Status::fail(
      "fields 'width_px' x 'height_px' must be 8000x6000, 4000x3000, 5160x3890, 5664x4248 or 0x0 "
      "(4000x3000), got " +
      std::to_string(width_px) + "x" + std::to_string(height_px));
}

Result<PreciseReshoot> PreciseReshoot::create(const PreciseReshootGoal& goal,
                                              const std::optional<p::VisibleStatus>& latest_visible,
                                              double now_s) {
  Result<p::ReshootResolution> resolution = reshoot_resolution(goal.width_px, goal.height_px);
  if (!resolution) return resolution.status();
  // 0x000005 reads the value as uint16 x 0.01 mm, so the same scale goes back.
  constexpr double kFocalStepMm = 0.01;
  constexpr double kMaxFocalMm = 65535 * kFocalStepMm;
  const Status focal_valid =
      p::check_range("focal_length_mm", goal.focal_length_mm, 0.0, kMaxFocalMm, "mm");
  if (!focal_valid) return focal_valid;
  const Status zoom_valid =
      p::check_range("zoom_ratio", goal.zoom_x, p::kMinZoomRatio, p::kMaxZoomRatio, "x");
  if (!zoom_valid) return zoom_valid;
  double focal_mm = goal.focal_length_mm;
  if (focal_mm == 0) {
    if (!latest_visible) {
      return Status::fail(
          "field 'focal_length_mm' is 0 (take it from visible/status) but no visible status "
          "(0x000005) has been received yet");
    }
    focal_mm = latest_visible->precise_shot_focal_length_mm;
  }
  p::PreciseReshootRequest request;
  request.lens = static_cast<p::PhotoLensMode>(goal.lens);
  request.resolution = resolution.value();
  request.zoom_x = goal.zoom_x;
  request.focal_length_raw = static_cast<uint16_t>(std::lround(focal_mm / kFocalStepMm));
  request.folder = goal.folder;
  request.name = goal.name;
  const Status valid = request.validate();
  if (!valid) return valid;
  const TimeoutChoice timeout = choose_timeout(goal.timeout_s, kDefaultTimeoutS);
  if (!timeout.ok) return Status::fail(timeout.error);
  return PreciseReshoot(request, timeout.seconds, now_s);
}

PreciseReshoot::PreciseReshoot(const p::PreciseReshootRequest& request, double timeout_s,
                               double now_s)
    : request_(request),
      tracker_("precise re-shoot", "precise re-shoot status 0x020307 'done'", timeout_s, now_s) {}

// ---- TF-card upgrade -------------------------------------------------------------------------

Result<TfUpgrade> TfUpgrade::create(double timeout_s, double now_s) {
  const TimeoutChoice timeout = choose_timeout(timeout_s, kDefaultTimeoutS);
  if (!timeout.ok) return Status::fail(timeout.error);
  return TfUpgrade(timeout.seconds, now_s);
}

TfUpgrade::TfUpgrade(double timeout_s, double now_s)
    : tracker_("TF-card upgrade", "TF-card upgrade status 0x02030C 'succeeded'", timeout_s, now_s) {
}

void TfUpgrade::on_progress(const p::CameraUpgradeStatus& status) {
  // 0x000008 also reports calibrations ("repairing"); only "upgrading" is this operation's.
  if (status.state != p::CameraUpgradeState::kUpgrading || tracker_.done()) return;
  progress_percent_ = status.progress_percent;
}

}  // namespace k40t::operations
