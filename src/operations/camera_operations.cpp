#include "k40t_driver/operations/camera_operations.h"

#include <cmath>
#include <cstdio>

#include "k40t_driver/codec/enum_names.h"

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

// The step a status gives: the state's phase in `phases` (any state not there: failed) and its
// text.
template <class E, size_t N>
Step step_for(E state, const EnumTo<E, Phase> (&phases)[N]) {
  return step(lookup(phases, state, Phase::kFailed), state_text(state));
}

std::string ratio_text(double ratio_x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1fx", ratio_x);
  return text;
}

}  // namespace

Step zoom_step(const p::ZoomStatus& status) {
  return status.progress == p::ZoomProgress::kDone ? step(Phase::kSucceeded, "done")
                                                   : step(Phase::kRunning, "zooming");
}

Step sd_format_step(const p::SdFormatStatus& status) {
  static constexpr EnumTo<p::SdFormatState, Phase> kPhases[] = {
      {p::SdFormatState::kDone, Phase::kSucceeded},
      {p::SdFormatState::kFormatting, Phase::kRunning}};
  return step_for(status.state, kPhases);  // failed, unavailable: failed
}

Step reshoot_step(const p::PreciseReshootStatus& status) {
  static constexpr EnumTo<p::ReshootState, Phase> kPhases[] = {
      {p::ReshootState::kDone, Phase::kSucceeded},
      {p::ReshootState::kReshooting, Phase::kRunning},
      {p::ReshootState::kBurst, Phase::kRunning},
      {p::ReshootState::kContinuous, Phase::kRunning},
      {p::ReshootState::kTimeLapse, Phase::kRunning},
      {p::ReshootState::kSingleShot, Phase::kRunning}};
  return step_for(status.state, kPhases);  // stopped, failed, the SD card states 7..11: failed
}

Step tf_upgrade_step(const p::TfCardUpgradeStatus& status) {
  static constexpr EnumTo<p::TfUpgradeState, Phase> kPhases[] = {
      {p::TfUpgradeState::kSucceeded, Phase::kSucceeded},
      {p::TfUpgradeState::kUpgrading, Phase::kRunning}};
  return step_for(status.state, kPhases);  // failed: failed
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
  return with_timeout(timeout_s, kDefaultTimeoutS,
                      [&](double seconds) { return ZoomTo(request, seconds, now_s); });
}

ZoomTo::ZoomTo(const p::ZoomRatioRequest& request, double timeout_s, double now_s)
    : TrackedOperation("zoom", "the ratio in visible status 0x000005", timeout_s, now_s),
      request_(request) {}

bool ZoomTo::arrived() const {
  // Both carry the ratio x10 on the wire: equal to a tenth.
  return ratio_x_ && std::lround(*ratio_x_ * 10) == std::lround(request_.zoom_x * 10);
}

void ZoomTo::on_status(const p::ZoomStatus& status) {
  const Step step = zoom_step(status);
  if (step.phase != Phase::kSucceeded) return tracker().report(step);
  if (arrived()) return tracker().report(step);
  reports_after_done_ = 0;  // the next reports decide
}

void ZoomTo::on_visible(const p::VisibleStatus& status) {
  ratio_x_ = status.zoom_x;
  if (arrived()) return tracker().report(step(Phase::kSucceeded, "at " + ratio_text(*ratio_x_)));
  if (reports_after_done_ < 0 || ++reports_after_done_ < kReportsAfterDone) return;
  tracker().report(step(Phase::kFailed, "the pod reported done at " + ratio_text(*ratio_x_) +
                                            ", not the " + ratio_text(request_.zoom_x) +
                                            " asked for"));
}

// ---- SD format -------------------------------------------------------------------------------

Result<SdFormat> SdFormat::create(double timeout_s, double now_s) {
  return with_timeout(timeout_s, kDefaultTimeoutS,
                      [&](double seconds) { return SdFormat(seconds, now_s); });
}

SdFormat::SdFormat(double timeout_s, double now_s)
    : TrackedOperation("SD format", "SD format status 0x02030D 'done'", timeout_s, now_s) {}

// ---- precise re-shoot ------------------------------------------------------------------------

namespace {
constexpr double kMaxFocalMm = 65535 / kReshootFocalUnitsPerMm;
}  // namespace

Result<p::PreciseReshootRequest> reshoot_request(const ReshootArgs& args,
                                                 const std::optional<p::VisibleStatus>& latest) {
  using R = Result<p::PreciseReshootRequest>;
  const bool current_zoom = args.zoom_ratio == 0;
  const bool current_focal = args.focal_length_mm == 0;
  if ((current_zoom || current_focal) && !latest) {
    return R::fail(std::string("field '") + (current_zoom ? "zoom_ratio" : "focal_length_mm") +
                   "' is 0 (the current value) but no visible/status report (0x000005) has come "
                   "yet: give it explicitly");
  }
  const double focal_mm =
      current_focal ? latest->precise_shot_focal_length_mm : args.focal_length_mm;
  const double zoom = current_zoom ? latest->zoom_x : args.zoom_ratio;
  const Status range =
      p::first_failure(p::check_range("zoom_ratio", zoom, 1.0, 160.0, "x"),
                       p::check_range("focal_length_mm", focal_mm, 0.0, kMaxFocalMm, "mm"));
  if (!range) return R::fail(range.message());
  p::PreciseReshootRequest r;
  r.lens = static_cast<p::PhotoLensMode>(args.lens);
  r.resolution = static_cast<p::ReshootResolution>(args.resolution);
  // What the wire carries (uint16 x10, rounded as the encoder rounds), so that the service's and
  // the action's "what was sent" is the ratio sent, not the one asked for (2.34 goes out as 2.3).
  r.zoom_x = std::round(zoom * 10) / 10;
  r.focal_length_raw = static_cast<uint16_t>(std::lround(focal_mm * kReshootFocalUnitsPerMm));
  r.folder = args.folder;
  r.name = args.name;
  const Status valid = r.validate();  // lens, resolution, zoom, folder and name
  if (!valid) return R::fail(valid.message());
  return r;
}

Result<PreciseReshoot> PreciseReshoot::create(const PreciseReshootGoal& goal,
                                              const std::optional<p::VisibleStatus>& latest_visible,
                                              double now_s) {
  Result<p::PreciseReshootRequest> request = reshoot_request(goal.args, latest_visible);
  if (!request) return request.status();
  return with_timeout(goal.timeout_s, kDefaultTimeoutS, [&](double seconds) {
    return PreciseReshoot(request.value(), seconds, now_s);
  });
}

PreciseReshoot::PreciseReshoot(const p::PreciseReshootRequest& request, double timeout_s,
                               double now_s)
    : TrackedOperation("precise re-shoot", "precise re-shoot status 0x020307 'done'", timeout_s,
                       now_s),
      request_(request) {}

// ---- TF-card upgrade -------------------------------------------------------------------------

Result<TfUpgrade> TfUpgrade::create(double timeout_s, double now_s) {
  return with_timeout(timeout_s, kDefaultTimeoutS,
                      [&](double seconds) { return TfUpgrade(seconds, now_s); });
}

TfUpgrade::TfUpgrade(double timeout_s, double now_s)
    : TrackedOperation("TF-card upgrade", "TF-card upgrade status 0x02030C 'succeeded'", timeout_s,
                       now_s) {}

void TfUpgrade::on_progress(const p::CameraUpgradeStatus& status) {
  // 0x000008 also reports calibrations ("repairing"); only "upgrading" is this operation's.
  if (status.state != p::CameraUpgradeState::kUpgrading || tracker().done()) return;
  progress_percent_ = status.progress_percent;
}

}  // namespace k40t::operations
