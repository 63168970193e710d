// Pinhole intrinsics as ROS's CameraInfo holds them (K 3x3 and P 3x4, row-major; distortion is
// not touched by zoom here), and how zoom and resizing change them. Pixel coordinates follow ROS
// and OpenCV: pixel centres at integers, the image centre at ((w - 1) / 2, (h - 1) / 2).
#pragma once

#include <array>

#include <opencv2/core/types.hpp>

namespace k40t::video {

struct Intrinsics {
  std::array<double, 9> K{};
  std::array<double, 12> P{};
  int width = 0;
  int height = 0;
};

// An ideal pinhole of focal length `focal_px` with the principal point at the image centre.
Intrinsics ideal_pinhole(double focal_px, int width, int height);

// Optical zoom by `factor`: focal lengths scale, the principal point stays where it is.
Intrinsics zoom_optical(const Intrinsics& in, double factor);
// Digital zoom by `factor`: a centred crop of 1/factor scaled back to full size — focal lengths
// scale and the principal point moves away from the centre by the same factor.
Intrinsics zoom_digital(const Intrinsics& in, double factor);
// The same camera at another resolution (calibrated at one stream size, streamed at another).
Intrinsics resized(const Intrinsics& in, int width, int height);
// The image shown scaled by `scale` with its top-left corner at (x, y) inside a larger frame of
// `frame_width` x `frame_height` (a split-screen panel).
Intrinsics placed(const Intrinsics& in, double scale, double x, double y, int frame_width,
                  int frame_height);
// `in` (the whole picture of one lens) scaled to the width of `panel` and placed there, inside
// a frame of `frame` size (split screen).
Intrinsics in_panel(const Intrinsics& in, const cv::Rect& panel, const cv::Size& frame);

}  // namespace k40t::video
