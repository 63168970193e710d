// The pod's three imaging lenses, all boresighted with the gimbal (no parallax at the scene's
// distances). Optics chosen to resemble the K40T: a 1/2.8" 16:9 telephoto zoom with 11x optical
// zoom and digital zoom up to 160x hybrid, a fixed wide lens with 1..8x digital zoom, and a
// 640x512 12 um thermal core behind a 13 mm lens with 1..8x digital zoom.
#pragma once

namespace k40t::sim {

enum class Lens { kTele, kWide, kThermal };

struct FieldOfView {
  double horizontal_deg = 0;
  double vertical_deg = 0;
};

struct LensSpec {
  double focal_length_mm = 0;  // at 1x
  double sensor_width_mm = 0;
  double sensor_height_mm = 0;
  double max_optical_zoom = 1;  // above it, zoom is digital (a crop)
  double max_zoom = 1;          // hybrid maximum
};

const LensSpec& lens_spec(Lens lens);

// Optical and digital parts of a hybrid zoom ratio for `lens` (zoom clamped to 1..max_zoom).
double optical_zoom(Lens lens, double zoom);
double digital_zoom(Lens lens, double zoom);
// Focal length actually set on the glass: follows the optical part only.
double focal_length_mm(Lens lens, double zoom);
// What the image covers at this hybrid zoom: optical zoom lengthens the focal length, digital zoom
// crops the image by the same factor.
FieldOfView field_of_view(Lens lens, double zoom);

// Pixel counts of the thermal core.
constexpr int kThermalWidthPx = 640;
constexpr int kThermalHeightPx = 512;

}  // namespace k40t::sim
