#include "k40t_driver/sim/video/clip.h"

#include <vector>

namespace k40t::sim::video {

std::optional<std::pair<cv::Point2d, cv::Point2d>> clip_segment(cv::Point2d a, cv::Point2d b,
                                                                const cv::Rect2d& box) {
  const cv::Point2d d = b - a;
  double t0 = 0;
  double t1 = 1;
  // For each edge: p * t <= q keeps the point inside.
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - box.x, box.x + box.width - a.x, a.y - box.y, box.y + box.height - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return std::nullopt;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) {
      if (t > t1) return std::nullopt;
      if (t > t0) t0 = t;
    } else {
      if (t < t0) return std::nullopt;
      if (t < t1) t1 = t;
    }
  }
  return std::make_pair(a + d * t0, a + d * t1);
}

namespace {
// One Sutherland-Hodgman pass against the half-plane v.*axis >= bound (`keep_above`) or
// v.*axis <= bound; a segment from inside to outside (or back) is cut where it meets the edge.
std::vector<cv::Point2d> clip_edge(const std::vector<cv::Point2d>& in, double cv::Point2d::*axis,
                                   double bound, bool keep_above) {
  double cv::Point2d::*other = axis == &cv::Point2d::x ? &cv::Point2d::y : &cv::Point2d::x;
  const auto inside = [&](const cv::Point2d& v) {
    return keep_above ? v.*axis >= bound : v.*axis <= bound;
  };
  const auto cross = [&](const cv::Point2d& a, const cv::Point2d& b) {
    cv::Point2d at;
    at.*axis = bound;
    at.*other = a.*other + (b.*other - a.*other) * (bound - a.*axis) / (b.*axis - a.*axis);
    return at;
  };
  std::vector<cv::Point2d> out;
  for (size_t i = 0; i < in.size(); ++i) {
    const cv::Point2d& cur = in[i];
    const cv::Point2d& prev = in[(i + in.size() - 1) % in.size()];
    if (inside(cur)) {
      if (!inside(prev)) out.push_back(cross(prev, cur));
      out.push_back(cur);
    } else if (inside(prev)) {
      out.push_back(cross(prev, cur));
    }
  }
  return out;
}
}  // namespace

std::vector<cv::Point2d> clip_polygon(const std::vector<cv::Point2d>& polygon,
                                      const cv::Rect2d& box) {
  std::vector<cv::Point2d> p = clip_edge(polygon, &cv::Point2d::x, box.x, true);
  p = clip_edge(p, &cv::Point2d::x, box.x + box.width, false);
  p = clip_edge(p, &cv::Point2d::y, box.y, true);
  return clip_edge(p, &cv::Point2d::y, box.y + box.height, false);
}

}  // namespace k40t::sim::video
