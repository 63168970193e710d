#include "k40t_driver/sim/lens.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/sim/geometry.h"

namespace k40t::sim {

namespace {
// 4.7 mm x 11 = 51.7 mm, 61.6 x 37.1 deg at 1x.
constexpr LensSpec kTele{4.7, 5.6, 3.15, 11.0, 160.0};
// 4.0 mm on a 6.17 mm wide 16:9 area: 75 x 47 deg.
constexpr LensSpec kWide{4.0, 6.17, 3.47, 1.0, 8.0};
// 640 x 512 pixels of 12 um behind 13 mm: 32.9 x 26.6 deg.
constexpr LensSpec kThermal{13.0, kThermalWidthPx * 0.012, kThermalHeightPx * 0.012, 1.0, 8.0};

double clamp_zoom(const LensSpec& spec, double zoom) {
  return std::clamp(zoom, 1.0, spec.max_zoom);
}
double full_angle_deg(double half_size_mm, double focal_mm) {
  return 2.0 * rad_to_deg(std::atan(half_size_mm / focal_mm));
}
}  // namespace

const LensSpec& lens_spec(Lens lens) {
  switch (lens) {
    case Lens::kTele:
      return kTele;
    case Lens::kWide:
      return kWide;
    case Lens::kThermal:
      break;
  }
  return kThermal;
}

double optical_zoom(Lens lens, double zoom) {
  const LensSpec& spec = lens_spec(lens);
  return std::min(clamp_zoom(spec, zoom), spec.max_optical_zoom);
}

double digital_zoom(Lens lens, double zoom) {
  return clamp_zoom(lens_spec(lens), zoom) / optical_zoom(lens, zoom);
}

double focal_length_mm(Lens lens, double zoom) {
  return lens_spec(lens).focal_length_mm * optical_zoom(lens, zoom);
}

FieldOfView field_of_view(Lens lens, double zoom) {
  const LensSpec& spec = lens_spec(lens);
  // A digital crop by d has the same angles as a focal length d times longer.
  const double effective_focal = spec.focal_length_mm * clamp_zoom(spec, zoom);
  return {full_angle_deg(spec.sensor_width_mm / 2, effective_focal),
          full_angle_deg(spec.sensor_height_mm / 2, effective_focal)};
}

}  // namespace k40t::sim
