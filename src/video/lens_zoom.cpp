#include "k40t_driver/video/lens_zoom.h"

#include <algorithm>

namespace k40t::video {

TeleZoom tele_zoom(double one_x_focal_mm, double max_optical_zoom, const ZoomState& zoom,
                   double reference_focal_mm) {
  const double ratio = std::max(1.0, zoom.zoom_ratio);
  const double focal = zoom.focal_length_mm > 0
                           ? zoom.focal_length_mm
                           : one_x_focal_mm * std::min(ratio, max_optical_zoom);
  TeleZoom out;
  out.optical = focal / reference_focal_mm;
  out.digital = std::max(1.0, ratio * one_x_focal_mm / focal);
  return out;
}

}  // namespace k40t::video
