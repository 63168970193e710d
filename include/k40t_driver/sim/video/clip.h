// Clipping in floating point before drawing: at 160x zoom a scene feature a few degrees across
// projects hundreds of thousands of pixels wide, beyond what OpenCV's integer drawing takes.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace k40t::sim::video {

// The part of segment a-b inside `box` (Liang-Barsky), nothing when none of it is.
std::optional<std::pair<cv::Point2d, cv::Point2d>> clip_segment(cv::Point2d a, cv::Point2d b,
                                                                const cv::Rect2d& box);

// A convex or concave polygon cut to `box` (Sutherland-Hodgman); empty when wholly outside.
std::vector<cv::Point2d> clip_polygon(const std::vector<cv::Point2d>& polygon,
                                      const cv::Rect2d& box);

}  // namespace k40t::sim::video
