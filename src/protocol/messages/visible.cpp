#include "k40t_driver/protocol/messages/visible.h"

#include "k40t_driver/protocol/cfg_enum_names.h"
#include "setting_bytes.h"

namespace k40t::protocol {

const char* to_string(VideoResolution resolution) {
  return cfg_enums::description_of(cfg_enums::video_resolution, static_cast<int>(resolution));
}

const char* to_string(PhotoResolution resolution) {
  return cfg_enums::description_of(cfg_enums::photo_resolution, static_cast<int>(resolution));
}

const char* to_string(Iso iso) {
  return cfg_enums::description_of(cfg_enums::iso, static_cast<int>(iso));
}

const char* to_string(Shutter shutter) {
  return cfg_enums::description_of(cfg_enums::shutter, static_cast<int>(shutter));
}

const char* to_string(ExposureValue ev) {
  return cfg_enums::description_of(cfg_enums::ev, static_cast<int>(ev));
}

const char* to_string(WhiteBalance white_balance) {
  return cfg_enums::constant_of(cfg_enums::white_balance, static_cast<int>(white_balance), "wb_");
}

const char* to_string(AntiFlicker anti_flicker) {
  return cfg_enums::constant_of(cfg_enums::anti_flicker, static_cast<int>(anti_flicker),
                                "flicker_");
}

const char* to_string(MeteringMode mode) {
  return cfg_enums::constant_of(cfg_enums::metering, static_cast<int>(mode), "metering_");
}

double video_bitrate_mbps(uint8_t code, VideoResolution resolution, bool h265) {
  if (code > kVisibleBitrateCodeMax) return 0;
  // Section 3.2.3.1 byte 5, one row per resolution, codes 0..3.
  static constexpr double kH264[3][4] = {{6, 8, 10, 12}, {30, 40, 50, 60}, {40, 55, 70, 80}};
  static constexpr double kH265[3][4] = {{3, 4, 5, 6}, {15, 20, 25, 30}, {20, 25, 35, 40}};
  int row = 0;
  switch (resolution) {
    case VideoResolution::k1920x1080:
      row = 0;
      break;
    case VideoResolution::k3840x2160:
      row = 1;
      break;
    case VideoResolution::k4000x3000:
      row = 2;
      break;
    default:
      return 0;
  }
  return h265 ? kH265[row][code] : kH264[row][code];
}

// ---- 0x010200 ------------------------------------------------------------------------------
Status VisibleSettingsAck::finish_decode(size_t payload_size) const {
  return detail::settings_follow(payload_size, code, kSettingsSize);
}

// ---- 0x000202 ------------------------------------------------------------------------------
Status VisiblePhotoResolutionRequest::validate() const {
  if (photo_resolution == PhotoResolution::k5160x3870) {
    return Status::fail(
        "field 'photo_resolution' has no settable code 22 (5160x3870 is only reported); "
        "allowed: 20 (8000x6000), 21 (4000x3000)");
  }
  return check_enum("photo_resolution", photo_resolution);
}

}  // namespace k40t::protocol
