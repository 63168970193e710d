// Visible-light (zoom) camera messages (document sections 3.2.1.3 and 3.2.3, system 0x04): the
// 5 Hz status report 0x000005, the settings read 0x000200 with its data ACK 0x010200, and the
// setting requests 0x000201..0x00020B (ACK: response code only). Every setting request starts
// with the byte 0x00 "start setting"; 0x000205 (EV) and 0x000206 (white balance) exist only in
// the Chinese original. Switches coded 0x01 on / 0x02 off are bools here.
// Ambiguities and decisions: docs/protocol/thermal_visible.md.
#pragma once

#include <type_traits>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/setting_request.h"

namespace k40t::protocol {

// Section 3.2.3.2 (recording resolution).
enum class VideoResolution : uint8_t { k1920x1080 = 0x08, k3840x2160 = 0x26, k4000x3000 = 0x36 };
const char* to_string(VideoResolution resolution);

// Section 3.2.3.1 byte 3; 0x000202 (section 3.2.3.3) can set only 0x14 and 0x15.
enum class PhotoResolution : uint8_t { k8000x6000 = 0x14, k4000x3000 = 0x15, k5160x3870 = 0x16 };
const char* to_string(PhotoResolution resolution);

// Section 3.2.3.4.
enum class Iso : uint8_t {
  kAuto = 0x00,
  k100 = 0x01,
  k200 = 0x02,
  k400 = 0x03,
  k800 = 0x04,
  k1600 = 0x05,
  k3200 = 0x06,
  k6400 = 0x07,
};
const char* to_string(Iso iso);

// Section 3.2.3.5; the document gives 0x0C twice, docs/protocol/decisions.md#a7 makes 0x0D =
// 1/6000.
enum class Shutter : uint8_t {
  kAuto = 0x00,
  k1_4 = 0x01,
  k1_8 = 0x02,
  k1_15 = 0x03,
  k1_30 = 0x04,
  k1_60 = 0x05,
  k1_125 = 0x06,
  k1_250 = 0x07,
  k1_500 = 0x08,
  k1_1000 = 0x09,
  k1_2000 = 0x0A,
  k1_4000 = 0x0B,
  k1_5000 = 0x0C,
  k1_6000 = 0x0D,
  k1_8000 = 0x0E,
};
const char* to_string(Shutter shutter);

// Sections 3.2.1.3 byte 6 and 3.2.3.6: exposure compensation codes.
enum class ExposureValue : uint8_t {
  kAuto = 0x00,
  kPlus2 = 0x0A,
  kPlus1 = 0x10,
  kZero = 0x16,
  kMinus1 = 0x1C,
  kMinus2 = 0x23,
};
const char* to_string(ExposureValue ev);

// Section 3.2.3.7 (bits 3..0 of the byte; bits 7..4 reserved).
enum class WhiteBalance : uint8_t {
  kAuto = 1,
  kIncandescent = 2,
  kFluorescent = 3,
  kWarmFluorescent = 4,
  kDaylight = 5,
  kCloudy = 6,
  kDusk = 7,
  kDark = 8,
};
const char* to_string(WhiteBalance white_balance);

// Section 3.2.3.8.
enum class AntiFlicker : uint8_t { kOff = 1, k50Hz = 2, k60Hz = 3, kAuto = 4 };
const char* to_string(AntiFlicker anti_flicker);

// Section 3.2.3.12.
enum class MeteringMode : uint8_t { kCenterWeighted = 1, kArea = 2, kAverage = 3 };
const char* to_string(MeteringMode mode);

// Section 3.2.3.1 byte 5: the recording bitrate in Mbit/s that a code 0..3 stands for, which
// depends on the recording resolution and the encoder (H.265 is the pod's default). 0 for a
// combination the document does not list.
double video_bitrate_mbps(uint8_t code, VideoResolution resolution, bool h265);

constexpr int kVisibleBitrateCodeMax = 3;
constexpr int kVisibleLevelMax = 100;     // zoom fine-tune, backlight, strong-light values
constexpr uint8_t kVisibleOnCode = 0x01;  // the switches: 0x01 on, 0x02 off
constexpr uint8_t kVisibleOffCode = 0x02;

// The family's one-byte settings: 0x00 "start setting", the value byte (setting_request.h).
template <class Self>
using VisibleSetting = ByteSettingRequest<Self, SettingPrefix::kStartSetting, 0>;

// ---- 0x000005, section 3.2.1.3, 5 Hz ---------------------------------------------------------
struct VisibleStatus {
  // kMinSize: the reserved last byte is optional on receive
  K40T_POD_REPORT(0x000005, "visible_status", "3.2.1.3", 15, 14);

  bool zooming = false;        // 0x00 zoom done, 0x01 zooming
  double focal_length_mm = 0;  // uint16 x0.01 mm
  double zoom_x = 0;           // uint16 x0.1, optical and digital combined (digital above 11x)
  ExposureValue ev = ExposureValue::kAuto;
  double iso_db = 0;  // uint16 x0.1 dB
  uint16_t shutter_us = 0;
  bool ae_lock_on = false;                  // 0x01 on, 0x02 off
  bool focusing = false;                    // 0x00 focus done, 0x01 focusing
  double precise_shot_focal_length_mm = 0;  // uint16, unit not given: read as 0.01 mm

  K40T_LAYOUT(s, v) {
    constexpr auto centi_mm = wire::scaled<uint16_t>(100).range(0.0, 655.35, "mm");
    // A report is what the pod says: flags are "non-zero", AE lock is "0x01".
    v("zooming", s.zooming, wire::u8);
    v("focal_length_mm", s.focal_length_mm, centi_mm);
    v("zoom_x", s.zoom_x, wire::scaled<uint16_t>(10).range(0.0, 6553.5, "x"));
    v("ev", s.ev, wire::u8);
    v("iso_db", s.iso_db, wire::scaled<uint16_t>(10).range(0.0, 6553.5, "dB"));
    v("shutter_us", s.shutter_us, wire::u16);
    v("ae_lock_on", s.ae_lock_on, wire::report_flag(kVisibleOnCode, kVisibleOffCode));
    v("focusing", s.focusing, wire::u8);
    v("precise_shot_focal_length_mm", s.precise_shot_focal_length_mm, centi_mm);
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// ---- 0x010200, section 3.2.3.1: every visible-camera setting ---------------------------------
// Response code (byte order docs/protocol/decisions.md#a2), then 15 bytes. A refusal may carry the
// response code only.
struct VisibleSettingsAck {
  K40T_POD_DATA_ACK(0x010200, "visible_read_settings_ack", "3.2.3.1", kPodToHost, 17);
  static constexpr size_t kSettingsSize = 15;  // after the code

  ResponseCode code = ResponseCode::kOk;
  PhotoResolution photo_resolution = PhotoResolution::k4000x3000;
  VideoResolution video_resolution = VideoResolution::k1920x1080;
  uint8_t video_bitrate_code = 0;  // 0..3, see video_bitrate_mbps()
  WhiteBalance white_balance = WhiteBalance::kAuto;
  ExposureValue ev = ExposureValue::kAuto;
  Iso iso = Iso::kAuto;
  Shutter shutter = Shutter::kAuto;
  uint8_t zoom_fine_tune = 0;      // 0..100
  bool backlight_on = false;       // byte 13 bit 7
  uint8_t backlight_value = 0;     // byte 13 bits 6..0
  bool strong_light_on = false;    // byte 14 bit 7
  uint8_t strong_light_value = 0;  // byte 14 bits 6..0
  bool ae_lock_on = false;
  bool watermark_on = false;                      // byte 16 bits 3..0
  AntiFlicker anti_flicker = AntiFlicker::kAuto;  // byte 16 bits 7..4
  MeteringMode metering = MeteringMode::kArea;

  K40T_LAYOUT(s, v) {
    constexpr auto level = wire::u8.range(0, kVisibleLevelMax);
    v("code", s.code, wire::response_code);
    v("photo_resolution", s.photo_resolution, wire::u8);
    v("video_resolution", s.video_resolution, wire::u8);
    v("video_bitrate_code", s.video_bitrate_code, wire::u8.range(0, kVisibleBitrateCodeMax));
    v("white_balance", s.white_balance, wire::u8.mask(0x0F));  // bits 7..4 reserved
    v("reserved", wire::gap, wire::reserved(2));
    v("ev", s.ev, wire::u8);
    v("iso", s.iso, wire::u8);
    v("shutter", s.shutter, wire::u8);
    v("zoom_fine_tune", s.zoom_fine_tune, level);
    v("backlight",
      switch_and_level("backlight_on", s.backlight_on, "backlight_value", s.backlight_value,
                       kVisibleLevelMax),
      wire::packed8);
    v("strong_light",
      switch_and_level("strong_light_on", s.strong_light_on, "strong_light_value",
                       s.strong_light_value, kVisibleLevelMax),
      wire::packed8);
    v("ae_lock_on", s.ae_lock_on, wire::report_flag(kVisibleOnCode, kVisibleOffCode));
    v("osd",
      wire::bit_group(wire::in_bits("watermark_on", s.watermark_on, wire::bits(0, 4)),
                      wire::in_bits("anti_flicker", s.anti_flicker, wire::bits(4, 4))),
      wire::packed8);
    v("metering", s.metering, wire::u8);
  }
  // A code-only ACK is a refusal; otherwise the settings must follow.
  Status finish_decode(size_t payload_size) const;
};

// ---- 0x000200, section 3.2.3.1: byte 1 = 0x01 "read all settings", byte 2 reserved -----------
struct VisibleReadSettingsRequest : ReadAllSettingsRequest<VisibleSettingsAck> {
  K40T_POD_MESSAGE(0x000200, "visible_read_settings", "3.2.3.1");
};

// ---- 0x000201, section 3.2.3.2: 0x00 start setting, resolution ------------------------------
struct VisibleVideoResolutionRequest : VisibleSetting<VisibleVideoResolutionRequest> {
  K40T_POD_MESSAGE(0x000201, "visible_set_video_resolution", "3.2.3.2");
  K40T_SETTING_VALUE(VideoResolution, video_resolution, VideoResolution::k1920x1080);
};

// ---- 0x000202, section 3.2.3.3: 0x00 start setting, 0x14 or 0x15 ----------------------------
struct VisiblePhotoResolutionRequest : VisibleSetting<VisiblePhotoResolutionRequest> {
  K40T_POD_MESSAGE(0x000202, "visible_set_photo_resolution", "3.2.3.3");
  K40T_SETTING_VALUE(PhotoResolution, photo_resolution, PhotoResolution::k4000x3000);

  Status validate() const;  // 0x16 (5160x3870) is reported by 0x010200 but cannot be set
};

// ---- 0x000203, section 3.2.3.4: 0x00 start setting, ISO code --------------------------------
struct VisibleIsoRequest : VisibleSetting<VisibleIsoRequest> {
  K40T_POD_MESSAGE(0x000203, "visible_set_iso", "3.2.3.4");
  K40T_SETTING_VALUE(Iso, iso, Iso::kAuto);
};

// ---- 0x000204, section 3.2.3.5: 0x00 start setting, shutter code ----------------------------
struct VisibleShutterRequest : VisibleSetting<VisibleShutterRequest> {
  K40T_POD_MESSAGE(0x000204, "visible_set_shutter", "3.2.3.5");
  K40T_SETTING_VALUE(Shutter, shutter, Shutter::kAuto);
};

// ---- 0x000205, section 3.2.3.6 (Chinese original only): 0x00 start setting, EV code ---------
struct VisibleEvRequest : VisibleSetting<VisibleEvRequest> {
  K40T_POD_MESSAGE(0x000205, "visible_set_ev", "3.2.3.6");
  K40T_SETTING_VALUE(ExposureValue, ev, ExposureValue::kAuto);
};

// ---- 0x000206, section 3.2.3.7 (Chinese original only): 0x00 start setting, white balance in
// bits 3..0 (bits 7..4 reserved), 2 reserved bytes -----------------------------------------------
struct VisibleWhiteBalanceRequest
    : ByteSettingRequest<VisibleWhiteBalanceRequest, SettingPrefix::kStartSetting, 2> {
  K40T_POD_MESSAGE(0x000206, "visible_set_white_balance", "3.2.3.7");
  static constexpr uint8_t kValueMask = 0x0F;  // bits 7..4 reserved
  K40T_SETTING_VALUE(WhiteBalance, white_balance, WhiteBalance::kAuto);
};

// ---- 0x000207, section 3.2.3.8: 0x00 start setting, anti-flicker code -----------------------
struct VisibleAntiFlickerRequest : VisibleSetting<VisibleAntiFlickerRequest> {
  K40T_POD_MESSAGE(0x000207, "visible_set_anti_flicker", "3.2.3.8");
  K40T_SETTING_VALUE(AntiFlicker, anti_flicker, AntiFlicker::kAuto);
};

// "0x00 start setting, 0x01 on / 0x02 off, value 0..100": strong-light suppression (3.2.3.9)
// and backlight compensation (3.2.3.10). A request derives from SwitchAndValueRequest<Self> and
// declares its two fields with K40T_SETTING_SWITCH and K40T_SETTING_VALUE (setting_request.h); the
// base turns them into the request's layout.
template <class Derived>
struct SwitchAndValueRequest {
  using Self = Derived;
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 3;
  static constexpr size_t kMinSize = 3;
  using Ack = PlainAck;

  K40T_LAYOUT(s, v) {
    using Self = std::conditional_t<std::is_const_v<S_>, const Derived, Derived>;
    auto& self = static_cast<Self&>(s);
    v("start", wire::gap, wire::fixed(kStartSettingByte, "start setting"));
    v(Derived::kOnName, self.*Derived::kOn, wire::flag(kVisibleOnCode, kVisibleOffCode));
    v(Derived::kValueName, self.*Derived::kValue, wire::u8.range(0, kVisibleLevelMax));
  }
};

// ---- 0x000208, section 3.2.3.9: 0x00 start setting, 0x01 on / 0x02 off, value 0..100 --------
// The pod cannot have strong-light suppression and backlight compensation on at once (note of
// 3.2.3.9/3.2.3.10): that depends on the pod's state, so the session or the simulator enforces
// it, not this struct.
struct VisibleStrongLightRequest : SwitchAndValueRequest<VisibleStrongLightRequest> {
  K40T_POD_MESSAGE(0x000208, "visible_set_strong_light", "3.2.3.9");

  K40T_SETTING_SWITCH(strong_light_on, false);
  K40T_SETTING_VALUE(uint8_t, strong_light_value, 0);
};

// ---- 0x000209, section 3.2.3.10: 0x00 start setting, 0x01 on / 0x02 off, value 0..100 -------
// Not together with strong-light suppression (see VisibleStrongLightRequest).
struct VisibleBacklightRequest : SwitchAndValueRequest<VisibleBacklightRequest> {
  K40T_POD_MESSAGE(0x000209, "visible_set_backlight", "3.2.3.10");

  K40T_SETTING_SWITCH(backlight_on, false);
  K40T_SETTING_VALUE(uint8_t, backlight_value, 0);
};

// ---- 0x00020A, section 3.2.3.11: 0x00 start setting, 0x01 on / 0x02 off --------------------
struct VisibleAeLockRequest : VisibleSetting<VisibleAeLockRequest> {
  K40T_POD_MESSAGE(0x00020A, "visible_set_ae_lock", "3.2.3.11");
  K40T_SETTING_CODES(kVisibleOnCode, kVisibleOffCode);
  K40T_SETTING_VALUE(bool, ae_lock_on, false);
};

// ---- 0x00020B, section 3.2.3.12: 0x00 start setting, metering mode --------------------------
struct VisibleMeteringRequest : VisibleSetting<VisibleMeteringRequest> {
  K40T_POD_MESSAGE(0x00020B, "visible_set_metering", "3.2.3.12");
  K40T_SETTING_VALUE(MeteringMode, metering, MeteringMode::kArea);
};

// Every message struct of the visible family: the catalogue, the catalogue tests and the fuzz
// target take their entries from this list (message_list.h).
using VisibleMessages =
    MessageList<VisibleStatus, VisibleReadSettingsRequest, VisibleSettingsAck,
                VisibleVideoResolutionRequest, VisiblePhotoResolutionRequest, VisibleIsoRequest,
                VisibleShutterRequest, VisibleEvRequest, VisibleWhiteBalanceRequest,
                VisibleAntiFlickerRequest, VisibleStrongLightRequest, VisibleBacklightRequest,
                VisibleAeLockRequest, VisibleMeteringRequest>;

}  // namespace k40t::protocol
