#include "k40t_driver/sim/camera_settings.h"

#include <array>
#include <cmath>

namespace k40t::sim {

double shutter_code_us(uint8_t code) {
  // 1/4 .. 1/8000 s; docs/protocol/decisions.md#a7 reads the document's second 0x0C as 0x0D =
  // 1/6000.
  static constexpr std::array<double, 15> kDenominators = {
      0, 4, 8, 15, 30, 60, 125, 250, 500, 1000, 2000, 4000, 5000, 6000, 8000};
  if (code == 0 || code >= kDenominators.size()) return 0;
  return 1e6 / kDenominators[code];
}

double iso_code_db(uint8_t code) {
  if (code < 1 || code > 7) return 0;  // auto: the simulated scene is bright, ISO 100
  return 20.0 * std::log10(std::pow(2.0, code - 1));
}

double stream_bitrate_mbps(uint8_t code) {
  static constexpr std::array<double, 7> kMbps = {0, 1, 1.5, 2, 4, 8, 12};
  return code < kMbps.size() ? kMbps[code] : 0;
}

double visible_video_mbps(uint8_t resolution, uint8_t bitrate) {
  static constexpr std::array<double, 4> k1080p = {6, 8, 10, 12};
  static constexpr std::array<double, 4> k4k = {30, 40, 50, 60};
  static constexpr std::array<double, 4> k12mp = {40, 55, 70, 80};
  const size_t i = bitrate < 4 ? bitrate : 1;
  switch (resolution) {
    case 0x26:
      return k4k[i];
    case 0x36:
      return k12mp[i];
    default:
      return k1080p[i];
  }
}

VisibleSettings factory_visible_settings() {
  namespace p = protocol;
  VisibleSettings v;
  v.photo_resolution = p::PhotoResolution::k4000x3000;
  v.video_resolution = p::VideoResolution::k1920x1080;
  v.video_bitrate_code = 1;  // 0..3 within the resolution's table
  v.white_balance = p::WhiteBalance::kAuto;
  v.ev = p::ExposureValue::kAuto;
  v.iso = p::Iso::kAuto;
  v.shutter = p::Shutter::kAuto;
  v.zoom_fine_tune = 50;
  v.backlight_on = false;
  v.backlight_value = 0;
  v.strong_light_on = false;
  v.strong_light_value = 0;
  v.ae_lock_on = false;
  v.anti_flicker = p::AntiFlicker::kAuto;
  v.metering = p::MeteringMode::kCenterWeighted;
  return v;
}

}  // namespace k40t::sim
