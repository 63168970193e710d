// Thermal camera setting requests, sections 3.2.2.2 .. 3.2.2.15 (ACK: response code only). The
// settings read and the status report are in thermal.h; enums and ranges in thermal_types.h.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/setting_request.h"
#include "k40t_driver/protocol/messages/thermal_types.h"

namespace k40t::protocol {

// ---- 0x000105, section 3.2.2.2: 1 = no zoom, 2..8 = digital zoom ----------------------------
struct ThermalZoomRequest : ByteSettingRequest<ThermalZoomRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x000105;
  static constexpr const char* kName = "thermal_set_zoom";
  static constexpr const char* kSection = "3.2.2.2";
  static constexpr int64_t kMin = kThermalZoomMin;
  static constexpr int64_t kMax = kThermalZoomMax;

  uint8_t zoom_x = 1;
  static constexpr auto kValue = &ThermalZoomRequest::zoom_x;
  static constexpr const char* kValueName = "zoom_x";
};

// ---- 0x000106, section 3.2.2.3 -------------------------------------------------------------
struct ThermalPaletteRequest : ByteSettingRequest<ThermalPaletteRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x000106;
  static constexpr const char* kName = "thermal_set_palette";
  static constexpr const char* kSection = "3.2.2.3";

  Palette palette = Palette::kWhiteHot;
  static constexpr auto kValue = &ThermalPaletteRequest::palette;
  static constexpr const char* kValueName = "palette";
};

// ---- 0x000108, section 3.2.2.4: on the wire 0x00 = on, 0x01 = off --------------------------
// While measurement is on the pod sends 0x000004 periodically.
struct ThermalMeasurementRequest
    : ByteSettingRequest<ThermalMeasurementRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x000108;
  static constexpr const char* kName = "thermal_set_measurement";
  static constexpr const char* kSection = "3.2.2.4";
  static constexpr uint8_t kOnCode = 0x00;  // inverted: 0 = on
  static constexpr uint8_t kOffCode = 0x01;

  bool measurement_on = true;
  static constexpr auto kValue = &ThermalMeasurementRequest::measurement_on;
  static constexpr const char* kValueName = "measurement_on";
};

// ---- 0x00010A, section 3.2.2.5: 0..100 -----------------------------------------------------
struct ThermalSharpnessRequest
    : ByteSettingRequest<ThermalSharpnessRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x00010A;
  static constexpr const char* kName = "thermal_set_sharpness";
  static constexpr const char* kSection = "3.2.2.5";
  static constexpr int64_t kMin = 0;
  static constexpr int64_t kMax = kThermalLevelMax;

  uint8_t sharpness = 0;
  static constexpr auto kValue = &ThermalSharpnessRequest::sharpness;
  static constexpr const char* kValueName = "sharpness";
};

// ---- 0x00010B, section 3.2.2.6: 0..100 -----------------------------------------------------
struct ThermalBrightnessRequest
    : ByteSettingRequest<ThermalBrightnessRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x00010B;
  static constexpr const char* kName = "thermal_set_brightness";
  static constexpr const char* kSection = "3.2.2.6";
  static constexpr int64_t kMin = 0;
  static constexpr int64_t kMax = kThermalLevelMax;

  uint8_t brightness = 0;
  static constexpr auto kValue = &ThermalBrightnessRequest::brightness;
  static constexpr const char* kValueName = "brightness";
};

// ---- 0x00010C, section 3.2.2.7: 0..100 -----------------------------------------------------
struct ThermalContrastRequest
    : ByteSettingRequest<ThermalContrastRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x00010C;
  static constexpr const char* kName = "thermal_set_contrast";
  static constexpr const char* kSection = "3.2.2.7";
  static constexpr int64_t kMin = 0;
  static constexpr int64_t kMax = kThermalLevelMax;

  uint8_t contrast = 0;
  static constexpr auto kValue = &ThermalContrastRequest::contrast;
  static constexpr const char* kValueName = "contrast";
};

// ---- 0x00010D, section 3.2.2.8: switch (0 off, 1 on), level 0..100, reserved ---------------
struct ThermalDenoiseRequest {
  static constexpr MessageId kId = 0x00010D;
  static constexpr const char* kName = "thermal_set_denoise";
  static constexpr const char* kSection = "3.2.2.8";
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 3;
  static constexpr size_t kMinSize = 2;
  using Ack = PlainAck;

  bool denoise_on = false;
  uint8_t denoise_level = 0;

  K40T_MESSAGE_LAYOUT()
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("denoise_on", s.denoise_on, wire::flag(1, 0));
    v("denoise_level", s.denoise_level, wire::u8.range(0, kThermalLevelMax));
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// ---- 0x00010E, section 3.2.2.9: 0 = off, 1..10 = level -------------------------------------
struct ThermalEnhancementRequest
    : ByteSettingRequest<ThermalEnhancementRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x00010E;
  static constexpr const char* kName = "thermal_set_enhancement";
  static constexpr const char* kSection = "3.2.2.9";
  static constexpr int64_t kMin = 0;
  static constexpr int64_t kMax = kThermalEnhancementMax;

  uint8_t enhancement_level = 0;
  static constexpr auto kValue = &ThermalEnhancementRequest::enhancement_level;
  static constexpr const char* kValueName = "enhancement_level";
};

// ---- 0x00010F, section 3.2.2.10: spot measurement cursor, uint16 x 0..1920, y 0..1088 -------
struct ThermalSpotRequest {
  static constexpr MessageId kId = 0x00010F;
  static constexpr const char* kName = "thermal_set_spot";
  static constexpr const char* kSection = "3.2.2.10";
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 5;
  static constexpr size_t kMinSize = 4;
  using Ack = PlainAck;

  uint16_t x_px = 0;
  uint16_t y_px = 0;

  K40T_MESSAGE_LAYOUT()
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("x_px", s.x_px, wire::u16.range(0, kThermalPictureWidth));
    v("y_px", s.y_px, wire::u16.range(0, kThermalPictureHeight));
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// ---- 0x000110, section 3.2.2.11: measurement rectangle, uint16 width, height, centre x, y ----
// The rectangle must lie inside the measurable area x 320..1279, y 32..1023 (the note of
// 3.2.2.11, read as: centre +- half the size stays inside).
struct ThermalAreaRequest {
  static constexpr MessageId kId = 0x000110;
  static constexpr const char* kName = "thermal_set_area";
  static constexpr const char* kSection = "3.2.2.11";
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 9;
  static constexpr size_t kMinSize = 8;
  using Ack = PlainAck;

  uint16_t width_px = 0;
  uint16_t height_px = 0;
  uint16_t center_x_px = 0;
  uint16_t center_y_px = 0;

  K40T_MESSAGE_LAYOUT()
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("width_px", s.width_px, wire::u16.range(1, kThermalMeasurableXMax - kThermalMeasurableXMin));
    v("height_px", s.height_px,
      wire::u16.range(1, kThermalMeasurableYMax - kThermalMeasurableYMin));
    v("center_x_px", s.center_x_px,
      wire::u16.range(kThermalMeasurableXMin, kThermalMeasurableXMax));
    v("center_y_px", s.center_y_px,
      wire::u16.range(kThermalMeasurableYMin, kThermalMeasurableYMax));
    v("reserved", wire::gap, wire::reserved(1));
  }
  Status extra_checks() const;  // the rectangle stays inside the measurable area
};

// ---- 0x000123, section 3.2.2.12 ------------------------------------------------------------
struct ThermalGainModeRequest
    : ByteSettingRequest<ThermalGainModeRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x000123;
  static constexpr const char* kName = "thermal_set_gain_mode";
  static constexpr const char* kSection = "3.2.2.12";

  ThermalGainMode gain_mode = ThermalGainMode::kHigh;
  static constexpr auto kValue = &ThermalGainModeRequest::gain_mode;
  static constexpr const char* kValueName = "gain_mode";
};

// ---- 0x000124, section 3.2.2.13: int16 x0.1 degC high, low, difference; 2 reserved ---------
// High/low -100.0..500.0 degC, difference 0.1..600.0 degC; -2732 on the wire switches one off.
struct ThermalAlarmsRequest {
  static constexpr MessageId kId = 0x000124;
  static constexpr const char* kName = "thermal_set_alarms";
  static constexpr const char* kSection = "3.2.2.13";
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 8;
  // docs/protocol/decisions.md#a9: the table says 7 bytes, the text 8.
  static constexpr size_t kMinSize = 7;
  using Ack = PlainAck;

  bool high_alarm_on = false;
  double high_alarm_degC = 0;
  bool low_alarm_on = false;
  double low_alarm_degC = 0;
  bool difference_alarm_on = false;
  double difference_alarm_degC = 0;

  K40T_MESSAGE_LAYOUT()
  template <class S, class V>
  static void layout(S& s, V&& v) {
    thermal_alarm_limits(s, v);
    v("reserved", wire::gap, wire::reserved(2));
  }
};

// ---- 0x000125, section 3.2.2.14: temperature overlay on the thermal picture ----------------
struct ThermalOverlayRequest : ByteSettingRequest<ThermalOverlayRequest, SettingPrefix::kNone, 1> {
  static constexpr MessageId kId = 0x000125;
  static constexpr const char* kName = "thermal_set_overlay";
  static constexpr const char* kSection = "3.2.2.14";
  static constexpr uint8_t kOnCode = 0x01;
  static constexpr uint8_t kOffCode = 0x00;

  bool overlay_on = false;
  static constexpr auto kValue = &ThermalOverlayRequest::overlay_on;
  static constexpr const char* kValueName = "overlay_on";
};

// ---- 0x000126, section 3.2.2.15: switch, int16 reference -30..50 degC, int16 float 0..80 degC
struct ThermalThresholdAlarmRequest {
  static constexpr MessageId kId = 0x000126;
  static constexpr const char* kName = "thermal_set_threshold_alarm";
  static constexpr const char* kSection = "3.2.2.15";
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 6;
  static constexpr size_t kMinSize = 5;
  using Ack = PlainAck;

  bool threshold_alarm_on = false;
  double threshold_reference_degC = 0;
  double threshold_float_degC = 0;

  K40T_MESSAGE_LAYOUT()
  template <class S, class V>
  static void layout(S& s, V&& v) {
    thermal_threshold_alarm(s, v, wire::flag(1, 0));
    v("reserved", wire::gap, wire::reserved(1));
  }
};

}  // namespace k40t::protocol
