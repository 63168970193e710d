#include "k40t_driver/video/intrinsics.h"

namespace k40t::video {

namespace {
// Indices of fx, cx, fy, cy in K and P, and of P's Tx/Ty (which scale like fx/fy).
constexpr int kFx = 0, kCx = 2, kFy = 4, kCy = 5;
constexpr int kPfx = 0, kPcx = 2, kPtx = 3, kPfy = 5, kPcy = 6, kPty = 7;

// Applies u' = a_u * u + b_u, v' = a_v * v + b_v to the camera's projection.
Intrinsics affine(const Intrinsics& in, double au, double bu, double av, double bv) {
  Intrinsics out = in;
  out.K[kFx] = in.K[kFx] * au;
  out.K[1] = in.K[1] * au;  // skew
  out.K[kCx] = in.K[kCx] * au + bu;
  out.K[kFy] = in.K[kFy] * av;
  out.K[kCy] = in.K[kCy] * av + bv;
  out.P[kPfx] = in.P[kPfx] * au;
  out.P[1] = in.P[1] * au;
  out.P[kPcx] = in.P[kPcx] * au + bu;
  out.P[kPtx] = in.P[kPtx] * au;
  out.P[kPfy] = in.P[kPfy] * av;
  out.P[kPcy] = in.P[kPcy] * av + bv;
  out.P[kPty] = in.P[kPty] * av;
  return out;
}
}  // namespace

Intrinsics ideal_pinhole(double focal_px, int width, int height) {
  Intrinsics out;
  const double cx = (width - 1) / 2.0;
  const double cy = (height - 1) / 2.0;
  out.K = {focal_px, 0, cx, 0, focal_px, cy, 0, 0, 1};
  out.P = {focal_px, 0, cx, 0, 0, focal_px, cy, 0, 0, 0, 1, 0};
  out.width = width;
  out.height = height;
  return out;
}

Intrinsics zoom_optical(const Intrinsics& in, double factor) {
  // Scaling about the principal point: u' = f (u - cx) + cx.
  return affine(in, factor, in.K[kCx] * (1 - factor), factor, in.K[kCy] * (1 - factor));
}

Intrinsics zoom_digital(const Intrinsics& in, double factor) {
  const double cu = (in.width - 1) / 2.0;
  const double cv = (in.height - 1) / 2.0;
  return affine(in, factor, cu * (1 - factor), factor, cv * (1 - factor));
}

Intrinsics resized(const Intrinsics& in, int width, int height) {
  // Pixel edges map to pixel edges: (u + 0.5) * s - 0.5.
  const double su = static_cast<double>(width) / in.width;
  const double sv = static_cast<double>(height) / in.height;
  Intrinsics out = affine(in, su, 0.5 * su - 0.5, sv, 0.5 * sv - 0.5);
  out.width = width;
  out.height = height;
  return out;
}

Intrinsics placed(const Intrinsics& in, double scale, double x, double y, int frame_width,
                  int frame_height) {
  Intrinsics out = affine(in, scale, 0.5 * scale - 0.5 + x, scale, 0.5 * scale - 0.5 + y);
  out.width = frame_width;
  out.height = frame_height;
  return out;
}

Intrinsics in_panel(const Intrinsics& in, const cv::Rect& panel, const cv::Size& frame) {
  return placed(in, static_cast<double>(panel.width) / in.width, panel.x, panel.y, frame.width,
                frame.height);
}

}  // namespace k40t::video
