#include "k40t_driver/sim/video/clip.h"

#include <functional>

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
// One Sutherland-Hodgman pass against the half-plane where inside(p) holds; `cross` gives the
// point where a segment from inside to outside (or back) meets the edge.
std::vector<cv::Point2d> clip_edge(
    const std::vector<cv::Point2d>& in, const std::function<bool(const cv::Point2d&)>& inside,
    const std::function<cv::Point2d(const cv::Point2d&, const cv::Point2d&)>& cross) {
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

cv::Point2d at_x(const cv::Point2d& a, const cv::Point2d& b, double x) {
  return {x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)};
}
cv::Point2d at_y(const cv::Point2d& a, const cv::Point2d& b, double y) {
  return {a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y), y};
}
}  // namespace

std::vector<cv::Point2d> clip_polygon(const std::vector<cv::Point2d>& polygon,
                                      const cv::Rect2d& box) {
  const double x0 = box.x;
  const double x1 = box.x + box.width;
  const double y0 = box.y;
  const double y1 = box.y + box.height;
  std::vector<cv::Point2d> p = polygon;
  p = clip_edge(
      p, [x0](const cv::Point2d& v) { return v.x >= x0; },
      [x0](const cv::Point2d& a, const cv::Point2d& b) { return at_x(a, b, x0); });
  p = clip_edge(
      p, [x1](const cv::Point2d& v) { return v.x <= x1; },
      [x1](const cv::Point2d& a, const cv::Point2d& b) { return at_x(a, b, x1); });
  p = clip_edge(
      p, [y0](const cv::Point2d& v) { return v.y >= y0; },
      [y0](const cv::Point2d& a, const cv::Point2d& b) { return at_y(a, b, y0); });
  p = clip_edge(
      p, [y1](const cv::Point2d& v) { return v.y <= y1; },
      [y1](const cv::Point2d& a, const cv::Point2d& b) { return at_y(a, b, y1); });
  return p;
}

}  // namespace k40t::sim::video
