// Thermal (infrared) camera messages (document sections 3.2.1.2 and 3.2.2, system 0x04): the 5 Hz
// status report 0x000004, the settings read 0x000100 with its data ACK 0x010100, and the setting
// requests 0x000105..0x000126 (ACK: response code only).
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
#include "k40t_driver/protocol/messages/thermal_settings.h"
#include "k40t_driver/protocol/messages/thermal_types.h"

namespace k40t::protocol {

// ---- 0x000004, section 3.2.1.2, 5 Hz ---------------------------------------------------------
// Area measurement fills max/min/centre/average and their coordinates; point measurement fills
// point_degC and its coordinates.
struct ThermalStatus {
  static constexpr MessageId kId = 0x000004;
  static constexpr const char* kName = "thermal_status";
  static constexpr const char* kSection = "3.2.1.2";
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 34;
  static constexpr size_t kMinSize = 30;  // the 4 reserved bytes are optional on receive

  double max_degC = 0;
  double min_degC = 0;
  double center_degC = 0;
  double point_degC = 0;
  double average_degC = 0;
  uint16_t max_x_px = 0;
  uint16_t max_y_px = 0;
  uint16_t min_x_px = 0;
  uint16_t min_y_px = 0;
  uint16_t center_x_px = 0;
  uint16_t center_y_px = 0;
  uint16_t point_x_px = 0;
  uint16_t point_y_px = 0;
  bool high_alarm = false;
  bool low_alarm = false;
  bool difference_alarm = false;
  bool threshold_alarm = false;

  K40T_MESSAGE_LAYOUT()
  template <class S, class V>
  static void layout(S& s, V&& v) {
    constexpr auto degC =
        wire::scaled<int16_t>(10).range(kThermalDeciDegMin, kThermalDeciDegMax, "degC");
    v("max_degC", s.max_degC, degC);
    v("min_degC", s.min_degC, degC);
    v("center_degC", s.center_degC, degC);
    v("point_degC", s.point_degC, degC);
    v("average_degC", s.average_degC, degC);
    v("max_x_px", s.max_x_px, wire::u16);
    v("max_y_px", s.max_y_px, wire::u16);
    v("min_x_px", s.min_x_px, wire::u16);
    v("min_y_px", s.min_y_px, wire::u16);
    v("center_x_px", s.center_x_px, wire::u16);
    v("center_y_px", s.center_y_px, wire::u16);
    v("point_x_px", s.point_x_px, wire::u16);
    v("point_y_px", s.point_y_px, wire::u16);
    // A report is what the pod says: any non-zero flag byte counts as "alarm".
    v("high_alarm", s.high_alarm, wire::u8);
    v("low_alarm", s.low_alarm, wire::u8);
    v("difference_alarm", s.difference_alarm, wire::u8);
    v("threshold_alarm", s.threshold_alarm, wire::u8);
    v("reserved", wire::gap, wire::reserved(4));
  }
};

// ---- 0x010100, section 3.2.2.1: every thermal setting ----------------------------------------
// Response code, then 21 bytes; multi-byte fields in the ACK byte order
// (docs/protocol/decisions.md#a2). A refusal may carry the response code only.
struct ThermalSettingsAck {
  static constexpr MessageId kId = 0x010100;
  static constexpr const char* kName = "thermal_read_settings_ack";
  static constexpr const char* kSection = "3.2.2.1";
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 23;
  static constexpr size_t kMinSize = 2;
  static constexpr auto kByteOrder = &CodecOptions::ack_byte_order;
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

  K40T_MESSAGE_LAYOUT()
  template <class S, class V>
  static void layout(S& s, V&& v) {
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
  static constexpr MessageId kId = 0x000100;
  static constexpr const char* kName = "thermal_read_settings";
  static constexpr const char* kSection = "3.2.2.1";
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
