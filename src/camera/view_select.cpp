#include "k40t_driver/camera/view_select.h"

#include <cstdlib>
#include <sstream>

namespace k40t::camera {

bool PixelRect::contains(double u, double v) const {
  if (width == 0 || height == 0) return true;
  // Pixel centres are at integers: the rectangle covers [x - 0.5, x + width - 0.5).
  return u >= x - 0.5 && u < x + width - 0.5 && v >= y - 0.5 && v < y + height - 0.5;
}

Result<std::optional<size_t>> select_view(int64_t image_stamp_ns,
                                          const std::vector<ViewCandidate>& panels, double u,
                                          double v, int64_t max_skew_ns) {
  std::ostringstream current;
  bool split = false;
  for (size_t i = 0; i < panels.size(); ++i) {
    const ViewCandidate& panel = panels[i];
    if (std::llabs(panel.stamp_ns - image_stamp_ns) > max_skew_ns) continue;  // an old split
    split = true;
    if (panel.roi.contains(u, v)) return std::optional<size_t>(i);
    current << (current.tellp() > 0 ? ", " : "") << panel.name << " x " << panel.roi.x << ".."
            << panel.roi.x + panel.roi.width - 1 << " y " << panel.roi.y << ".."
            << panel.roi.y + panel.roi.height - 1;
  }
  if (!split) return std::optional<size_t>();
  std::ostringstream why;
  why << "pixel (" << u << ", " << v << ") is in neither panel of the split screen ("
      << current.str() << ")";
  return Result<std::optional<size_t>>::fail(why.str());
}

}  // namespace k40t::camera
