// Which camera_info describes a pixel of the pod's one video stream. In split screen the video
// node publishes, beside the image's camera_info (the left, visible panel's), one camera_info per
// panel: K placed into the whole frame's pixel coordinates and the panel's rectangle as roi, each
// with the frame id of its own lens (docs/video.md). A pixel is located with the panel that
// contains it; a panel message counts only while it belongs to the current image (its stamp
// within `max_skew` of the image's camera_info: the video node stops publishing panels when the
// split screen ends).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/protocol/result.h"

namespace k40t::camera {

struct PixelRect {
  uint32_t x = 0, y = 0, width = 0, height = 0;  // width or height 0: the whole image
  bool contains(double u, double v) const;
};

struct ViewCandidate {
  int64_t stamp_ns = 0;
  PixelRect roi;
  std::string name;  // for messages: "visible panel", "thermal panel"
};

// The index in `panels` of the panel that holds (u, v); std::nullopt: no current panel, use the
// image's own camera_info; a failure: split screen, but the pixel is in neither panel.
Result<std::optional<size_t>> select_view(int64_t image_stamp_ns,
                                          const std::vector<ViewCandidate>& panels, double u,
                                          double v, int64_t max_skew_ns);

}  // namespace k40t::camera
