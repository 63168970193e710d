// How the pod's reported zoom splits into the tele's optical and digital zoom, ROS-free:
// ros/video/lens_models.cpp applies the factors to the tele's 1x intrinsics (intrinsics.h) for
// camera_info.
#pragma once

namespace k40t::video {

// What the pod last said about its zoom.
struct ZoomState {
  double focal_length_mm = 0;  // 0: not reported yet
  double zoom_ratio = 1;
  int thermal_zoom = 1;
};

// The tele's optical and digital zoom factors relative to intrinsics taken at
// `reference_focal_mm` (the calibration's focal length, or the 1x focal length of the nominal
// optics). The optical part is the reported focal length over the reference; before a focal
// length is reported, the 1x focal length times the ratio up to `max_optical_zoom`. The rest of
// the ratio (at least 1) is digital.
struct TeleZoom {
  double optical = 1;
  double digital = 1;
};
TeleZoom tele_zoom(double one_x_focal_mm, double max_optical_zoom, const ZoomState& zoom,
                   double reference_focal_mm);

}  // namespace k40t::video
