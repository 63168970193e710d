#include "k40t_driver/sim/video/palette.h"

#include <array>
#include <vector>

#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::sim::video {

namespace {

struct Stop {
  double at;  // 0..1 along the table
  int r, g, b;
};

using P = protocol::Palette;

// The palette's code (its name is the protocol's to_string, from cfg/setting_enums.txt) and stops.
struct PaletteSpec {
  P code;
  std::vector<Stop> stops;
};

// Colour stops chosen to resemble each palette as thermal cameras commonly draw it.
const std::array<PaletteSpec, kLastPalette>& palettes() {
  static const std::array<PaletteSpec, kLastPalette> kPalettes{{
      {P::kWhiteHot, {{0, 0, 0, 0}, {1, 255, 255, 255}}},
      {P::kBlackHot, {{0, 255, 255, 255}, {1, 0, 0, 0}}},
      {P::kRainbow,
       {{0, 0, 0, 128},
        {0.2, 0, 0, 255},
        {0.4, 0, 255, 255},
        {0.6, 0, 255, 0},
        {0.8, 255, 255, 0},
        {1, 255, 0, 0}}},
      {P::kHighContrastRainbow,  // the rainbow twice over: more colour steps per degree
       {{0, 0, 0, 255},
        {0.125, 0, 255, 0},
        {0.25, 255, 255, 0},
        {0.375, 255, 0, 0},
        {0.5, 0, 0, 255},
        {0.625, 0, 255, 0},
        {0.75, 255, 255, 0},
        {0.875, 255, 0, 0},
        {1, 255, 255, 255}}},
      {P::kIronRed,
       {{0, 0, 0, 0},
        {0.15, 30, 0, 100},
        {0.35, 130, 0, 150},
        {0.55, 220, 40, 40},
        {0.75, 250, 140, 0},
        {0.9, 255, 220, 60},
        {1, 255, 255, 230}}},
      {P::kMagma,
       {{0, 0, 0, 4},
        {0.25, 80, 18, 123},
        {0.5, 183, 55, 121},
        {0.75, 251, 136, 97},
        {1, 252, 253, 191}}},
      {P::kSky, {{0, 0, 0, 40}, {0.4, 0, 90, 200}, {0.75, 120, 200, 255}, {1, 255, 255, 255}}},
      {P::kMediumGrey, {{0, 64, 64, 64}, {1, 192, 192, 192}}},
      {P::kGreyRed, {{0, 0, 0, 0}, {0.8, 200, 200, 200}, {0.81, 200, 0, 0}, {1, 255, 60, 60}}},
      {P::kPurpleOrange, {{0, 40, 0, 80}, {0.5, 160, 60, 160}, {1, 255, 165, 0}}},
      {P::kSpecial1, {{0, 0, 20, 0}, {0.6, 0, 200, 60}, {1, 220, 255, 220}}},  // night-vision green
      {P::kWarningRed, {{0, 20, 20, 20}, {0.85, 210, 210, 210}, {0.86, 255, 0, 0}, {1, 255, 0, 0}}},
      {P::kIceFire,
       {{0, 180, 255, 255},
        {0.25, 0, 60, 255},
        {0.5, 0, 0, 0},
        {0.75, 255, 40, 0},
        {1, 255, 255, 160}}},
      {P::kCyanRed, {{0, 0, 255, 255}, {0.5, 128, 128, 128}, {1, 255, 0, 0}}},
      {P::kSpecial2, {{0, 0, 0, 160}, {0.5, 200, 0, 200}, {1, 255, 255, 0}}},
      {P::kGradientRed, {{0, 0, 0, 0}, {1, 255, 0, 0}}},
      {P::kGradientGreen, {{0, 0, 0, 0}, {1, 0, 255, 0}}},
      {P::kGradientYellow, {{0, 0, 0, 0}, {1, 255, 255, 0}}},
      {P::kWarningGreen,
       {{0, 20, 20, 20}, {0.85, 210, 210, 210}, {0.86, 0, 255, 0}, {1, 0, 255, 0}}},
      {P::kWarningBlue,  // the cold end marked
       {{0, 0, 0, 255}, {0.15, 0, 0, 255}, {0.16, 40, 40, 40}, {1, 230, 230, 230}}},
  }};
  return kPalettes;
}

Status check_palette(int palette) {
  if (palette < kFirstPalette || palette > kLastPalette ||
      static_cast<int>(palettes()[palette - 1].code) != palette) {
    return Status::fail("palette " + std::to_string(palette) + " is out of range " +
                        std::to_string(kFirstPalette) + ".." + std::to_string(kLastPalette));
  }
  return Status::ok();
}

cv::Vec3b interpolate(const std::vector<Stop>& stops, double t) {
  const Stop* lo = &stops.front();
  const Stop* hi = &stops.back();
  for (size_t i = 1; i < stops.size(); ++i) {
    if (t <= stops[i].at) {
      lo = &stops[i - 1];
      hi = &stops[i];
      break;
    }
  }
  const double span = hi->at - lo->at;
  const double f = span > 0 ? (t - lo->at) / span : 0;
  auto mix = [f](int a, int b) { return cv::saturate_cast<uchar>(a + (b - a) * f); };
  return {mix(lo->b, hi->b), mix(lo->g, hi->g), mix(lo->r, hi->r)};
}

}  // namespace

Result<std::string> palette_name(int palette) {
  if (Status s = check_palette(palette); !s) return s;
  return std::string(protocol::to_string(palettes()[palette - 1].code));
}

Result<cv::Mat> palette_table(int palette) {
  if (Status s = check_palette(palette); !s) return s;
  cv::Mat table(1, 256, CV_8UC3);
  const auto& stops = palettes()[palette - 1].stops;
  for (int i = 0; i < 256; ++i) table.at<cv::Vec3b>(0, i) = interpolate(stops, i / 255.0);
  return table;
}

}  // namespace k40t::sim::video
