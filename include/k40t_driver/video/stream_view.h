// What a frame of the pod's single stream shows, from the image mode the pod reports
// (0x000003 byte 4) and the frame's own size:
//   640 x 512                      the thermal camera, whatever the (possibly stale) mode says;
//   mode 7, any other size         split screen: the visible image at half size in the left half
//                                  (vertically centred), the thermal image scaled to the right
//                                  half's width (vertically centred) — the layout of the
//                                  simulator, to be checked against a real pod;
//   otherwise                      the visible camera: the telephoto for mode 5, and for mode 6
//                                  the lens configured for it (the document calls both
//                                  "visible").
// The mode comes at 1 Hz, the frames at 30 Hz: for the second after a mode change between visible
// and split screen the previous mode is still used (sizes are equal); thermal is never missed.
#pragma once

#include <optional>

#include <opencv2/core.hpp>

namespace k40t::video {

enum class Lens { kTele, kWide, kThermal };
const char* to_string(Lens lens);

constexpr int kThermalWidth = 640;
constexpr int kThermalHeight = 512;

struct StreamView {
  Lens lens = Lens::kTele;
  bool split = false;
};

StreamView stream_view(std::optional<int> image_mode, cv::Size frame, Lens mode6_lens);

struct SplitLayout {
  cv::Rect visible;
  cv::Rect thermal;
};
SplitLayout split_layout(cv::Size frame);

}  // namespace k40t::video
