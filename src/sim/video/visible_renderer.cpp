#include "k40t_driver/sim/video/visible_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/imgproc.hpp>

#include "k40t_driver/sim/video/pinhole_view.h"
#include "k40t_driver/sim/video/scene_canvas.h"

namespace k40t::sim::video {

namespace {

cv::Scalar mix(const cv::Scalar& a, const cv::Scalar& b, double f) {
  return a * (1 - f) + b * f;
}

// BGR colours of the landscape.
const cv::Scalar kSkyHorizon(235, 215, 190);
const cv::Scalar kSkyZenith(190, 110, 40);
const cv::Scalar kGroundHorizon(120, 150, 150);
const cv::Scalar kGroundNadir(40, 90, 60);
const cv::Scalar kGridLine(60, 70, 70);
const cv::Scalar kBlack(0, 0, 0);
const cv::Scalar kWhite(255, 255, 255);

// Each row is coloured by the elevation its centre pixel looks at (the gimbal does not roll).
void draw_sky_and_ground(cv::Mat& image, const PinholeView& view) {
  const double cx = (image.cols - 1) / 2.0;
  for (int row = 0; row < image.rows; ++row) {
    const double up = view.ray(cx, row).z;  // sine of the elevation
    const cv::Scalar colour = up >= 0 ? mix(kSkyHorizon, kSkyZenith, std::sqrt(up))
                                      : mix(kGroundHorizon, kGroundNadir, std::sqrt(-up));
    image.row(row).setTo(colour);
  }
}

void draw_heading_grid(SceneCanvas& canvas) {
  for (int heading = 0; heading < 360; heading += 10) {
    std::vector<Vec3> line;
    for (double elevation = -0.05; elevation > -89; elevation -= 5) {
      line.push_back(direction(heading, elevation));
    }
    canvas.polyline(line, kGridLine, heading % 90 == 0 ? 3 : 1);
    char text[8];
    std::snprintf(text, sizeof(text), "%03d", heading);
    canvas.label(direction(heading + 0.2, 0.4), text, 0.8, kBlack);
  }
  for (double elevation : {-2.0, -5.0, -10.0, -20.0, -30.0, -45.0, -60.0}) {
    std::vector<Vec3> circle;
    for (double heading = 0; heading <= 360; heading += 0.5) {
      circle.push_back(direction(heading, elevation));
    }
    canvas.polyline(circle, kGridLine, 1);
  }
}

// A tower every 30 deg on the horizon, each with a window a tenth of its size.
void draw_towers(SceneCanvas& canvas) {
  const cv::Scalar colours[] = {{40, 40, 200}, {200, 120, 40}, {40, 160, 220}, {150, 60, 150}};
  for (int i = 0; i < 12; ++i) {
    const double heading = i * 30 + 5;
    const double width = 2.0;
    const double height = 1.5 + (i % 3) * 1.5;
    canvas.fill({direction(heading, -0.3), direction(heading + width, -0.3),
                 direction(heading + width, height), direction(heading, height)},
                colours[i % 4]);
    const double w = width / 10;
    const double x = heading + width / 2 - w / 2;
    const double y = height * 0.7;
    canvas.fill(
        {direction(x, y), direction(x + w, y), direction(x + w, y + w), direction(x, y + w)},
        kWhite);
  }
}

// Ring targets at the four cardinal headings, 4 deg below the horizon: black and white discs
// halving from 1.6 deg down to 0.0125 deg (1.6 deg is ~90 px at 1x, 0.0125 deg ~90 px at 128x).
void draw_targets(SceneCanvas& canvas) {
  for (int heading = 0; heading < 360; heading += 90) {
    const Vec3 centre = direction(heading, -4);
    bool white = true;
    for (double radius = 1.6; radius > 0.01; radius /= 2) {
      canvas.disc(centre, radius, white ? kWhite : kBlack);
      white = !white;
    }
  }
}

void draw_osd(cv::Mat& image, const VideoSnapshot& snapshot) {
  char text[96];
  std::snprintf(text, sizeof(text), "TELE %.1fx  YAW %.1f  PITCH %.1f", snapshot.hybrid_zoom,
                snapshot.yaw_deg, snapshot.pitch_deg);
  const double scale = image.rows / 1080.0;
  cv::putText(image, text, cv::Point(16, image.rows - static_cast<int>(20 * scale)),
              cv::FONT_HERSHEY_SIMPLEX, scale, kWhite, std::max(1, static_cast<int>(2 * scale)),
              cv::LINE_AA);
}

}  // namespace

const cv::Mat& VisibleRenderer::render(const VideoSnapshot& snapshot, cv::Size size) {
  const ViewKey view{snapshot.yaw_deg, snapshot.pitch_deg, snapshot.hybrid_zoom, size.width,
                     size.height};
  if (valid_ && view == view_) return image_;
  image_.create(size, CV_8UC3);
  const PinholeView pinhole(snapshot.yaw_deg, snapshot.pitch_deg,
                            focal_px(Lens::kTele, snapshot.hybrid_zoom, size.width), size);
  draw_sky_and_ground(image_, pinhole);
  SceneCanvas canvas(image_, pinhole);
  draw_heading_grid(canvas);
  draw_towers(canvas);
  draw_targets(canvas);
  draw_osd(image_, snapshot);
  view_ = view;
  valid_ = true;
  return image_;
}

}  // namespace k40t::sim::video
