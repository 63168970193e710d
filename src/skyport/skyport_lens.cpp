// The bridge's lens commands (0x04): metering, focus, zoom. PSDK splits the zoom into an optical
// focal length and a digital factor on top; the pod has one hybrid ratio (1..160). The bridge keeps
// the split it commanded as long as the pod's ratio still equals its product; when the ratio moved
// otherwise (continuous zoom, another client), the split is derived from the pod's ratio: optical
// up to the lens's optical maximum, digital for the rest. Getters and the next set both use that
// split, so a set never jumps back to a stale value and what was set reads back as set.
#include <algorithm>
#include <cmath>

#include "k40t_driver/skyport/skyport_bridge.h"

namespace k40t::driver::skyport {

using namespace psdk;
using detail::refused;

namespace {
// The pod's stream is 1920x1080; a PSDK focus zone point becomes a box around it.
constexpr double kStreamWidth = 1920, kStreamHeight = 1080, kFocusBoxHalf = 100;

uint16_t clamp_px(double v, double hi) {
  return static_cast<uint16_t>(std::lround(std::clamp(v, 0.0, hi)));
}
}  // namespace

SkyportBridge::ZoomSplit SkyportBridge::zoom_split(const PodSnapshot& s) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const ZoomSplit commanded{optical_zoom_, digital_zoom_};
  if (!zoom_follows_pod_ || !s.have_visible || s.zoom_ratio <= 0) return commanded;
  const double optical = std::clamp(s.zoom_ratio, 1.0, options_.max_optical_zoom);
  return {optical, std::max(1.0, s.zoom_ratio / optical)};
}

AckCode SkyportBridge::apply_zoom(double optical, double digital) {
  const double ratio = optical * digital;
  if (ratio < 1.0 || ratio > options_.max_hybrid_zoom)
    return invalid("zoom " + std::to_string(ratio) + "x is outside the pod's 1.." +
                   std::to_string(options_.max_hybrid_zoom) + "x");
  const AckCode code = pod_code(pod_.set_zoom(ratio), "zoom");
  if (code == AckCode::kOk) {
    std::lock_guard<std::mutex> lock(mutex_);
    optical_zoom_ = optical;
    digital_zoom_ = digital;
    zoom_follows_pod_ = false;
  }
  return code;
}

template <class Set, class Get, class Mode, class Send>
void SkyportBridge::kept_mode(Mode SkyportBridge::*kept, Send send) {
  deferred<Set>([this, kept, send](const Set& c) {
    const AckCode code = send(c);
    if (code == AckCode::kOk) {
      std::lock_guard<std::mutex> lock(mutex_);  // Get reads it on the session thread
      this->*kept = c.mode;
    }
    return code;
  });
  session_.handle<Get>([this, kept](const Get&) {
    typename Get::Ack ack;
    std::lock_guard<std::mutex> lock(mutex_);
    ack.mode = this->*kept;
    return ack;
  });
}

void SkyportBridge::register_camera_lens() {
  kept_mode<SetMeteringMode, GetMeteringMode>(
      &SkyportBridge::metering_, [this](const SetMeteringMode& c) {
        // The pod meters centre-weighted (1), by area (2) or average (3): no spot metering.
        if (c.mode == MeteringMode::kSpot) return unsupported();
        return pod_code(pod_.set_metering(c.mode == MeteringMode::kCenter ? 1 : 3), "metering");
      });
  kept_mode<SetFocusMode, GetFocusMode>(&SkyportBridge::focus_mode_, [this](const SetFocusMode& c) {
    const bool autofocus = c.mode == FocusMode::kAuto;
    return pod_code(pod_.focus(autofocus ? PodFocus::kAuto : PodFocus::kManualStop, 0, 0, 0, 0),
                    "focus mode");
  });
  deferred<SetFocusZone>([this](const SetFocusZone& c) {
    const double x = c.x * kStreamWidth, y = c.y * kStreamHeight;
    const AckCode code =
        pod_code(pod_.focus(PodFocus::kArea, clamp_px(x - kFocusBoxHalf, kStreamWidth),
                            clamp_px(y - kFocusBoxHalf, kStreamHeight),
                            clamp_px(x + kFocusBoxHalf, kStreamWidth),
                            clamp_px(y + kFocusBoxHalf, kStreamHeight)),
                 "focus zone");
    if (code == AckCode::kOk) {
      std::lock_guard<std::mutex> lock(mutex_);
      focus_x_ = c.x;
      focus_y_ = c.y;
    }
    return code;
  });
  session_.handle<GetFocusZone>([this](const GetFocusZone&) {
    FocusZoneAck ack;
    std::lock_guard<std::mutex> lock(mutex_);
    ack.x = focus_x_;
    ack.y = focus_y_;
    return ack;
  });
  deferred<SetDigitalZoomFactor>([this](const SetDigitalZoomFactor& c) {
    const double max_digital = options_.max_hybrid_zoom / options_.max_optical_zoom;
    if (!(c.factor_x >= 1.0f) || c.factor_x > max_digital)
      return invalid("digital zoom " + std::to_string(c.factor_x) + "x is outside 1.." +
                     std::to_string(max_digital) + "x");
    return apply_zoom(zoom_split(pod_.snapshot()).optical, c.factor_x);
  });
  session_.handle<GetDigitalZoomFactor>([this](const GetDigitalZoomFactor&) {
    DigitalZoomFactorAck ack;
    ack.factor_x = static_cast<float>(zoom_split(pod_.snapshot()).digital);
    return ack;
  });
  session_.handle<GetDigitalZoomSpec>([this](const GetDigitalZoomSpec&) {
    DigitalZoomSpecAck ack;
    ack.max_factor_x = static_cast<float>(options_.max_hybrid_zoom / options_.max_optical_zoom);
    return ack;
  });
  session_.handle<GetOpticalZoomSpec>([this](const GetOpticalZoomSpec&) {
    OpticalZoomSpecAck ack;
    ack.min_focal_length_mm = options_.tele_focal_length_mm;
    ack.max_focal_length_mm = options_.tele_focal_length_mm * options_.max_optical_zoom;
    ack.focal_length_step_mm = 0.1;
    return ack;
  });
  deferred<SetOpticalZoomFocalLength>([this](const SetOpticalZoomFocalLength& c) {
    const double optical = c.focal_length_mm / options_.tele_focal_length_mm;
    if (optical < 1.0 - 1e-6 || optical > options_.max_optical_zoom + 1e-6)
      return invalid("focal length " + std::to_string(c.focal_length_mm) +
                     " mm is outside the lens's range");
    return apply_zoom(std::clamp(optical, 1.0, options_.max_optical_zoom),
                      zoom_split(pod_.snapshot()).digital);
  });
  session_.handle<GetOpticalZoomFocalLength>([this](const GetOpticalZoomFocalLength&) {
    OpticalZoomFocalLengthAck ack;
    ack.focal_length_mm = options_.tele_focal_length_mm * zoom_split(pod_.snapshot()).optical;
    return ack;
  });
  from_snapshot<GetOpticalZoomFactor>(&PodSnapshot::have_visible, [this](const PodSnapshot& s) {
    OpticalZoomFactorAck ack;
    ack.factor_x = static_cast<float>(zoom_split(s).optical);
    return ack;
  });
  deferred<StartContinuousZoom>([this](const StartContinuousZoom& c) {
    const AckCode code =
        pod_code(pod_.zoom(c.direction == ZoomDirection::kIn ? PodZoom::kIn : PodZoom::kOut),
                 "continuous zoom");
    if (code == AckCode::kOk) {
      std::lock_guard<std::mutex> lock(mutex_);
      zoom_follows_pod_ = true;  // where it stops, only the pod knows
    }
    return code;
  });
  deferred<StopContinuousZoom>(
      [this](const StopContinuousZoom&) { return pod_code(pod_.zoom(PodZoom::kStop), "zoom"); });
  // The pod has no focus ring position and no focus assistant.
  session_.handle<SetFocusAssistant>([this](const SetFocusAssistant&) { return unsupported(); });
  session_.handle<GetFocusAssistant>(
      [this](const GetFocusAssistant&) { return refused<FocusAssistantAck>(unsupported()); });
  session_.handle<GetFocusRingUpperBound>([this](const GetFocusRingUpperBound&) {
    return refused<FocusRingUpperBoundAck>(unsupported());
  });
  session_.handle<SetFocusRing>([this](const SetFocusRing&) { return unsupported(); });
  session_.handle<GetFocusRing>(
      [this](const GetFocusRing&) { return refused<FocusRingAck>(unsupported()); });
  session_.handle<SetSpotMeteringZone>(
      [this](const SetSpotMeteringZone&) { return unsupported(); });
  session_.handle<GetSpotMeteringZone>(
      [this](const GetSpotMeteringZone&) { return refused<SpotMeteringZoneAck>(unsupported()); });
}

}  // namespace k40t::driver::skyport
