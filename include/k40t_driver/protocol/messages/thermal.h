// Thermal (infrared) camera settings (document section 3.2.2, system 0x04): the setting requests
// 0x000105..0x000126 (ACK: response code only), the settings read 0x000100 with its data ACK
// 0x010100, and the family's message list. A new setting is written here once: its request, its
// field in the ACK, its entry in the list (docs/adding_a_setting.md). The 5 Hz status report
// 0x000004 is in thermal_status.h.
//
// Temperatures are int16 in 0.1 degC on the wire and double degC here. Alarm limits use -2732
// (absolute zero) on the wire for "off"; here each limit is an `_on` flag plus a value that is
// only meaningful (and only validated) when the flag is set. Pixel coordinates are in the
// 1920x1088 picture the document's measurement commands use (black border included).
// Ambiguities and decisions: docs/protocol/thermal_visible.md.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/setting_request.h"
#include "k40t_driver/protocol/messages/thermal_status.h"
#include "k40t_driver/protocol/messages/thermal_types.h"

namespace k40t::protocol {

// The family's one-byte settings: the value byte, one reserved byte (setting_request.h).
template <class Self>
using ThermalSetting = ByteSettingRequest<Self, SettingPrefix::kNone, 1>;

// ---- 0x000105, section 3.2.2.2: 1 = no zoom, 2..8 = digital zoom ----------------------------
struct ThermalZoomRequest : ThermalSetting<ThermalZoomRequest> {
  K40T_POD_MESSAGE(0x000105, "thermal_set_zoom", "3.2.2.2");
  K40T_SETTING_RANGE(kThermalZoomMin, kThermalZoomMax);
  K40T_SETTING_VALUE(uint8_t, zoom_x, 1);
};

// ---- 0x000106, section 3.2.2.3 -------------------------------------------------------------
struct ThermalPaletteRequest : ThermalSetting<ThermalPaletteRequest> {
  K40T_POD_MESSAGE(0x000106, "thermal_set_palette", "3.2.2.3");
  K40T_SETTING_VALUE(Palette, palette, Palette::kWhiteHot);
};

// ---- 0x000108, section 3.2.2.4: on the wire 0x00 = on, 0x01 = off --------------------------
// While measurement is on the pod sends 0x000004 periodically.
struct ThermalMeasurementRequest : ThermalSetting<ThermalMeasurementRequest> {
  K40T_POD_MESSAGE(0x000108, "thermal_set_measurement", "3.2.2.4");
  K40T_SETTING_CODES(0x00, 0x01);  // inverted: 0 = on
  K40T_SETTING_VALUE(bool, measurement_on, true);
};

// ---- 0x00010A, section 3.2.2.5: 0..100 -----------------------------------------------------
struct ThermalSharpnessRequest : ThermalSetting<ThermalSharpnessRequest> {
  K40T_POD_MESSAGE(0x00010A, "thermal_set_sharpness", "3.2.2.5");
  K40T_SETTING_RANGE(0, kThermalLevelMax);
  K40T_SETTING_VALUE(uint8_t, sharpness, 0);
};

// ---- 0x00010B, section 3.2.2.6: 0..100 -----------------------------------------------------
struct ThermalBrightnessRequest : ThermalSetting<ThermalBrightnessRequest> {
  K40T_POD_MESSAGE(0x00010B, "thermal_set_brightness", "3.2.2.6");
  K40T_SETTING_RANGE(0, kThermalLevelMax);
  K40T_SETTING_VALUE(uint8_t, brightness, 0);
};

// ---- 0x00010C, section 3.2.2.7: 0..100 -----------------------------------------------------
struct ThermalContrastRequest : ThermalSetting<ThermalContrastRequest> {
  K40T_POD_MESSAGE(0x00010C, "thermal_set_contrast", "3.2.2.7");
  K40T_SETTING_RANGE(0, kThermalLevelMax);
  K40T_SETTING_VALUE(uint8_t, contrast, 0);
};

// ---- 0x00010D, section 3.2.2.8: switch (0 off, 1 on), level 0..100, reserved ---------------
struct ThermalDenoiseRequest {
  K40T_POD_REQUEST(0x00010D, "thermal_set_denoise", "3.2.2.8", 3, 2);
  K40T_FIELDS((bool, denoise_on, wire::flag(1, 0)),
              (uint8_t, denoise_level, wire::u8.range(0, kThermalLevelMax)),
              (reserved, wire::reserved(1)));
};

// ---- 0x00010E, section 3.2.2.9: 0 = off, 1..10 = level -------------------------------------
struct ThermalEnhancementRequest : ThermalSetting<ThermalEnhancementRequest> {
  K40T_POD_MESSAGE(0x00010E, "thermal_set_enhancement", "3.2.2.9");
  K40T_SETTING_RANGE(0, kThermalEnhancementMax);
  K40T_SETTING_VALUE(uint8_t, enhancement_level, 0);
};

// ---- 0x00010F, section 3.2.2.10: spot measurement cursor, uint16 x 0..1920, y 0..1088 -------
struct ThermalSpotRequest {
  K40T_POD_REQUEST(0x00010F, "thermal_set_spot", "3.2.2.10", 5, 4);

  K40T_FIELDS((uint16_t, x_px, wire::u16.range(0, kThermalPictureWidth)),
              (uint16_t, y_px, wire::u16.range(0, kThermalPictureHeight)),
              (reserved, wire::reserved(1)));
};

// ---- 0x000110, section 3.2.2.11: measurement rectangle, uint16 width, height, centre x, y ----
// The rectangle must lie inside the measurable area x 320..1279, y 32..1023 (the note of
// 3.2.2.11, read as: centre +- half the size stays inside).
struct ThermalAreaRequest {
  K40T_POD_REQUEST(0x000110, "thermal_set_area", "3.2.2.11", 9, 8);

  K40T_FIELDS(
      (uint16_t, width_px, wire::u16.range(1, kThermalMeasurableXMax - kThermalMeasurableXMin)),
      (uint16_t, height_px, wire::u16.range(1, kThermalMeasurableYMax - kThermalMeasurableYMin)),
      (uint16_t, center_x_px, wire::u16.range(kThermalMeasurableXMin, kThermalMeasurableXMax)),
      (uint16_t, center_y_px, wire::u16.range(kThermalMeasurableYMin, kThermalMeasurableYMax)),
      (reserved, wire::reserved(1)));
  Status extra_checks() const;  // the rectangle stays inside the measurable area
};

// ---- 0x000123, section 3.2.2.12 ------------------------------------------------------------
struct ThermalGainModeRequest : ThermalSetting<ThermalGainModeRequest> {
  K40T_POD_MESSAGE(0x000123, "thermal_set_gain_mode", "3.2.2.12");
  K40T_SETTING_VALUE(ThermalGainMode, gain_mode, ThermalGainMode::kHigh);
};

// ---- 0x000124, section 3.2.2.13: int16 x0.1 degC high, low, difference; 2 reserved ---------
// High/low -100.0..500.0 degC, difference 0.1..600.0 degC; -2732 on the wire switches one off.
struct ThermalAlarmsRequest {
  // docs/protocol/decisions.md#a9: the table says 7 bytes, the text 8.
  K40T_POD_REQUEST(0x000124, "thermal_set_alarms", "3.2.2.13", 8, 7);

  bool high_alarm_on = false;
  double high_alarm_degC = 0;
  bool low_alarm_on = false;
  double low_alarm_degC = 0;
  bool difference_alarm_on = false;
  double difference_alarm_degC = 0;

  K40T_LAYOUT(s, v) {
    thermal_alarm_limits(s, v);
    v("reserved", wire::gap, wire::reserved(2));
  }
};

// ---- 0x000125, section 3.2.2.14: temperature overlay on the thermal picture ----------------
struct ThermalOverlayRequest : ThermalSetting<ThermalOverlayRequest> {
  K40T_POD_MESSAGE(0x000125, "thermal_set_overlay", "3.2.2.14");
  K40T_SETTING_CODES(0x01, 0x00);
  K40T_SETTING_VALUE(bool, overlay_on, false);
};

// ---- 0x000126, section 3.2.2.15: switch, int16 reference -30..50 degC, int16 float 0..80 degC
struct ThermalThresholdAlarmRequest {
  K40T_POD_REQUEST(0x000126, "thermal_set_threshold_alarm", "3.2.2.15", 6, 5);

  bool threshold_alarm_on = false;
  double threshold_reference_degC = 0;
  double threshold_float_degC = 0;

  K40T_LAYOUT(s, v) {
    thermal_threshold_alarm(s, v, wire::flag(1, 0));
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// ---- 0x010100, section 3.2.2.1: every thermal setting ----------------------------------------
// Response code, then 21 bytes; multi-byte fields in the ACK byte order
// (docs/protocol/decisions.md#a2). A refusal may carry the response code only.
struct ThermalSettingsAck {
  K40T_POD_DATA_ACK(0x010100, "thermal_read_settings_ack", "3.2.2.1", kPodToHost, 23);
  static constexpr size_t kSettingsMinSize = 19;  // after the code; the 2 reserved are optional

  ResponseCode code = ResponseCode::kOk;
  Palette palette = Palette::kWhiteHot;
  bool measurement_on = true;  // byte 4 bit 0, inverted on the wire (0 = on)
  ThermalMeasurementType measurement_type = ThermalMeasurementType::kPoint;
  ThermalCoreType core_type = ThermalCoreType::kRadiometric;
  uint8_t zoom_x = 1;  // byte 4 bits 3..7
  uint8_t sharpness = 0;
  ThermalGainMode gain_mode = ThermalGainMode::kHigh;
  uint8_t brightness = 0;
  uint8_t contrast = 0;
  bool denoise_on = false;        // byte 9 bit 7
  uint8_t denoise_level = 0;      // byte 9 bits 0..6
  bool enhancement_on = false;    // byte 10 bit 7 (see docs: the document says bit 0)
  uint8_t enhancement_level = 0;  // byte 10 bits 0..6
  bool high_alarm_on = false;
  double high_alarm_degC = 0;
  bool low_alarm_on = false;
  double low_alarm_degC = 0;
  bool difference_alarm_on = false;
  double difference_alarm_degC = 0;
  bool threshold_alarm_on = false;
  double threshold_reference_degC = 0;
  double threshold_float_degC = 0;

  K40T_LAYOUT(s, v) {
    constexpr auto level = wire::u8.range(0, kThermalLevelMax);
    v("code", s.code, wire::response_code);
    v("palette", s.palette, wire::u8);
    v("config",
      wire::bit_group(wire::in_bits("measurement_on", s.measurement_on, wire::inverted_bit(0)),
                      wire::in_bits("measurement_type", s.measurement_type, wire::bit(1)),
                      wire::in_bits("core_type", s.core_type, wire::bit(2)),
                      wire::in_bits("zoom_x", s.zoom_x,
                                    wire::bits(3, 5).range(kThermalZoomMin, kThermalZoomMax))),
      wire::packed8);
    v("sharpness", s.sharpness, level);
    v("gain_mode", s.gain_mode, wire::u8);
    v("brightness", s.brightness, level);
    v("contrast", s.contrast, level);
    v("denoise",
      switch_and_level("denoise_on", s.denoise_on, "denoise_level", s.denoise_level,
                       kThermalLevelMax),
      wire::packed8);
    v("enhancement",
      switch_and_level("enhancement_on", s.enhancement_on, "enhancement_level", s.enhancement_level,
                       kThermalEnhancementMax),
      wire::packed8);
    thermal_alarm_limits(s, v);
    thermal_threshold_alarm(s, v, wire::u8);  // any non-zero byte: on
    v("reserved", wire::gap, wire::reserved(2));
  }
  // A code-only ACK is a refusal; otherwise the settings must follow.
  Status finish_decode(size_t payload_size) const;
};

// ---- 0x000100, section 3.2.2.1: byte 1 = 0x01 "read all settings", byte 2 reserved -----------
struct ThermalReadSettingsRequest : ReadAllSettingsRequest<ThermalSettingsAck> {
  K40T_POD_MESSAGE(0x000100, "thermal_read_settings", "3.2.2.1");
};

// Every message struct of the thermal family: the catalogue, the catalogue tests and the fuzz
// target take their entries from this list (message_list.h).
using ThermalMessages =
    MessageList<ThermalStatus, ThermalReadSettingsRequest, ThermalSettingsAck, ThermalZoomRequest,
                ThermalPaletteRequest, ThermalMeasurementRequest, ThermalSharpnessRequest,
                ThermalBrightnessRequest, ThermalContrastRequest, ThermalDenoiseRequest,
                ThermalEnhancementRequest, ThermalSpotRequest, ThermalAreaRequest,
                ThermalGainModeRequest, ThermalAlarmsRequest, ThermalOverlayRequest,
                ThermalThresholdAlarmRequest>;

}  // namespace k40t::protocol
