#include "k40t_driver/protocol/messages/visible.h"

#include "k40t_driver/protocol/cfg_enum_names.h"
#include "setting_bytes.h"

namespace k40t::protocol {

using detail::check_level;
using detail::code_of;

const char* to_string(VideoResolution resolution) {
  return cfg_enums::description_of(cfg_enums::video_resolution, static_cast<int>(resolution));
}

const char* to_string(PhotoResolution resolution) {
  switch (resolution) {
    case PhotoResolution::k8000x6000:
      return "8000x6000";
    case PhotoResolution::k4000x3000:
      return "4000x3000";
    case PhotoResolution::k5160x3870:
      return "5160x3870";
  }
  return nullptr;
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
  switch (mode) {
    case MeteringMode::kCenterWeighted:
      return "center_weighted";
    case MeteringMode::kArea:
      return "area";
    case MeteringMode::kAverage:
      return "average";
  }
  return nullptr;
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

namespace {

constexpr uint8_t kOnWire = 0x01;  // the 0x01 on / 0x02 off switches
constexpr uint8_t kLowNibble = 0x0F;

uint8_t switch_to_wire(bool on) {
  return on ? kOnWire : 0x02;
}

}  // namespace

// ---- 0x000005 ------------------------------------------------------------------------------
Status VisibleStatus::validate() const {
  return first_failure(
      check_range("focal_length_mm", focal_length_mm, 0.0, 655.35, "mm"),
      check_range("zoom_x", zoom_x, 0.0, 6553.5, "x"), check_enum("ev", ev),
      check_range("iso_db", iso_db, 0.0, 6553.5, "dB"),
      check_range("precise_shot_focal_length_mm", precise_shot_focal_length_mm, 0.0, 655.35, "mm"));
}

void VisibleStatus::encode(ByteWriter& w, const CodecOptions&) const {
  w.u8(zooming ? 1 : 0);
  w.u16(to_wire<uint16_t>(focal_length_mm, 100));
  w.u16(to_wire<uint16_t>(zoom_x, 10));
  w.u8(code_of(ev));
  w.u16(to_wire<uint16_t>(iso_db, 10));
  w.u16(shutter_us);
  w.u8(switch_to_wire(ae_lock_on));
  w.u8(focusing ? 1 : 0);
  w.u16(to_wire<uint16_t>(precise_shot_focal_length_mm, 100));
  w.zeros(1);
}

Status VisibleStatus::decode(ByteReader& r, const CodecOptions&) {
  // A report is what the pod says: flags are "non-zero", AE lock is "0x01".
  zooming = r.u8() != 0;
  focal_length_mm = r.u16() / 100.0;
  zoom_x = r.u16() / 10.0;
  ev = static_cast<ExposureValue>(r.u8());
  iso_db = r.u16() / 10.0;
  shutter_us = r.u16();
  ae_lock_on = r.u8() == kOnWire;
  focusing = r.u8() != 0;
  precise_shot_focal_length_mm = r.u16() / 100.0;
  return Status::ok();
}

// ---- 0x010200 ------------------------------------------------------------------------------
Status VisibleSettingsAck::validate() const {
  return first_failure(
      check_enum("photo_resolution", photo_resolution),
      check_enum("video_resolution", video_resolution),
      check_level("video_bitrate_code", video_bitrate_code, 0, kVisibleBitrateCodeMax),
      check_enum("white_balance", white_balance), check_enum("ev", ev), check_enum("iso", iso),
      check_enum("shutter", shutter),
      check_level("zoom_fine_tune", zoom_fine_tune, 0, kVisibleLevelMax),
      check_level("backlight_value", backlight_value, 0, kVisibleLevelMax),
      check_level("strong_light_value", strong_light_value, 0, kVisibleLevelMax),
      check_enum("anti_flicker", anti_flicker), check_enum("metering", metering));
}

void VisibleSettingsAck::encode(ByteWriter& w, const CodecOptions& o) const {
  w.u16(static_cast<uint16_t>(code), o.ack_byte_order);
  w.u8(code_of(photo_resolution));
  w.u8(code_of(video_resolution));
  w.u8(video_bitrate_code);
  w.u8(code_of(white_balance));  // bits 7..4 reserved: zero
  w.zeros(2);
  w.u8(code_of(ev));
  w.u8(code_of(iso));
  w.u8(code_of(shutter));
  w.u8(zoom_fine_tune);
  w.u8(detail::pack_switch_and_level(backlight_on, backlight_value));
  w.u8(detail::pack_switch_and_level(strong_light_on, strong_light_value));
  w.u8(switch_to_wire(ae_lock_on));
  w.u8(static_cast<uint8_t>(code_of(anti_flicker) << 4 | (watermark_on ? 1 : 0)));
  w.u8(code_of(metering));
}

Status VisibleSettingsAck::decode(ByteReader& r, const CodecOptions& o) {
  code = static_cast<ResponseCode>(r.u16(o.ack_byte_order));
  bool has_settings = false;
  const Status follow = detail::settings_follow(r.remaining(), code, kSettingsSize, &has_settings);
  if (!follow || !has_settings) return follow;
  photo_resolution = static_cast<PhotoResolution>(r.u8());
  video_resolution = static_cast<VideoResolution>(r.u8());
  video_bitrate_code = r.u8();
  white_balance = static_cast<WhiteBalance>(r.u8() & kLowNibble);
  r.skip(2);
  ev = static_cast<ExposureValue>(r.u8());
  iso = static_cast<Iso>(r.u8());
  shutter = static_cast<Shutter>(r.u8());
  zoom_fine_tune = r.u8();
  detail::unpack_switch_and_level(r.u8(), &backlight_on, &backlight_value);
  detail::unpack_switch_and_level(r.u8(), &strong_light_on, &strong_light_value);
  ae_lock_on = r.u8() == kOnWire;
  const uint8_t osd = r.u8();
  watermark_on = (osd & kLowNibble) != 0;
  anti_flicker = static_cast<AntiFlicker>(osd >> 4);
  metering = static_cast<MeteringMode>(r.u8());
  return Status::ok();
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
