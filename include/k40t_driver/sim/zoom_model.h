// The telephoto camera's hybrid zoom (1..160x, optical up to 11x, section 3.2.4.5/3.2.4.6) and its
// focus (3.2.4.18). Zoom moves over time at a constant rate in log space (a doubling every
// `doubling_time_s`, as a zoom motor with digital zoom behind it looks to the user), emitting
// 0x020304 "zooming" when it starts and every `status_period_s` while it moves, and "done" when it
// stops. After a zoom the camera refocuses (if auto focus after zoom is on), and the focus
// commands make it busy too. The focus distance: manual focus (0x000313 codes 1/2, which way the
// reading focus_plus says) moves it nearer or farther in log space while it runs; auto focus
// (auto, one-touch, area, after a zoom) puts it back on the scene at `scene_distance_m`.
#pragma once

#include <optional>

#include "k40t_driver/sim/events.h"
#include "k40t_driver/sim/outcome.h"

namespace k40t::sim {

struct ZoomConfig {
  double min_zoom = 1;
  double max_zoom = 160;
  double doubling_time_s = 0.5;             // 1x -> 160x in ~3.7 s
  double step_factor = 1.4142135623730951;  // one "zoom in/out" step: half a doubling
  double status_period_s = 0.2;             // 0x020304 rate while zooming
  double focus_time_s = 0.6;                // auto focus, one-touch, area, and after a zoom
  double scene_distance_m = 100;            // where auto focus focuses
  double manual_focus_halving_s = 0.5;      // manual near halves the distance this often
  double min_focus_m = 1;
  double max_focus_m = 10000;
};

enum class ContinuousZoom { kIn, kOut, kStop, kStepIn, kStepOut };  // 0x000306 byte 1, 0..4
enum class FocusCommand {                                           // 0x000313 byte 1, 0..7
  kAuto,
  kManualNear,
  kManualFar,
  kStopManual,
  kArea,
  kOneTouch,
  kAutoAfterZoomOn,
  kAutoAfterZoomOff,
};

// The frame area auto focus (0x000313 mode 4) focuses on, in stream pixels (1920x1080).
struct FocusArea {
  int left = 0;
  int top = 0;
  int right = 0;
  int bottom = 0;
};

class ZoomModel {
 public:
  explicit ZoomModel(const ZoomConfig& config = {});

  Outcome set_zoom(double zoom);  // 0x000304: 1..160
  Outcome zoom_control(ContinuousZoom command);
  // Area auto focus uses `area` (refused unless it is a non-empty box inside the stream); the
  // other commands ignore it. Auto and one-touch focus, and any zoom, go back to centre focus
  // (3.2.4.18 note).
  Outcome focus(FocusCommand command, const FocusArea& area = {});

  void step(double dt_s, EventQueue& events);

  double zoom() const { return zoom_; }
  double target() const { return target_; }
  bool zooming() const { return moving_; }
  bool focusing() const { return manual_focus_ || focus_left_s_ > 0; }
  bool auto_focus_after_zoom() const { return auto_focus_after_zoom_; }
  double focus_distance_m() const { return focus_distance_m_; }
  // The area the camera focuses on; nullopt: the centre.
  const std::optional<FocusArea>& focus_area() const { return focus_area_; }
  // The telephoto focal length follows the optical part (lens.h).
  double focal_length_mm() const;
  void reset();  // factory settings: 1x, no motion

 private:
  void start(double target);

  ZoomConfig config_;
  double zoom_;
  double target_;
  bool moving_ = false;
  bool announce_start_ = false;
  double since_status_s_ = 0;
  bool manual_focus_ = false;
  bool manual_nearer_ = false;  // while manual_focus_: which way
  double focus_distance_m_ = 0;
  double focus_left_s_ = 0;
  bool auto_focus_after_zoom_ = true;
  std::optional<FocusArea> focus_area_;
};

}  // namespace k40t::sim
