// Thermal (infrared) camera: the enums and the document's ranges (sections 3.2.1.2 and 3.2.2), and
// the field groups the settings ACK 0x010100 shares with the setting requests. The messages are in
// thermal_status.h (the status report) and thermal.h (settings, their read-back, the list).
#pragma once

#include "k40t_driver/protocol/message_layout.h"

namespace k40t::protocol {

// Section 3.2.2.3 (names from the Chinese original; the translation has "high contrast red" for 4
// and "yellow red" for 14).
enum class Palette : uint8_t {
  kWhiteHot = 1,
  kBlackHot = 2,
  kRainbow = 3,
  kHighContrastRainbow = 4,
  kIronRed = 5,
  kMagma = 6,
  kSky = 7,
  kMediumGrey = 8,
  kGreyRed = 9,
  kPurpleOrange = 10,
  kSpecial1 = 11,
  kWarningRed = 12,
  kIceFire = 13,
  kCyanRed = 14,
  kSpecial2 = 15,
  kGradientRed = 16,
  kGradientGreen = 17,
  kGradientYellow = 18,
  kWarningGreen = 19,
  kWarningBlue = 20,
};
const char* to_string(Palette palette);

// Section 3.2.2.12.
enum class ThermalGainMode : uint8_t { kHigh = 0, kLow = 1, kAuto = 2 };
const char* to_string(ThermalGainMode mode);

// Section 3.2.2.1, byte 4 bit 1.
enum class ThermalMeasurementType : uint8_t { kPoint = 0, kArea = 1 };
const char* to_string(ThermalMeasurementType type);

// Section 3.2.2.1, byte 4 bit 2: the thermal core fitted ("movement" in the translation).
enum class ThermalCoreType : uint8_t { kSighting = 0, kRadiometric = 1 };
const char* to_string(ThermalCoreType type);

// The document's ranges (sections 3.2.2.1, 3.2.2.10, 3.2.2.11, 3.2.2.13, 3.2.2.15).
constexpr int kThermalZoomMin = 1;
constexpr int kThermalZoomMax = 8;
constexpr int kThermalLevelMax = 100;  // sharpness, brightness, contrast, denoise level
constexpr int kThermalEnhancementMax = 10;
constexpr int kThermalPictureWidth = 1920;  // spot x range 0..1920, black border included
constexpr int kThermalPictureHeight = 1088;
// The measurable part of that picture (note of 3.2.2.11): x 320..1279, y 32..1023.
constexpr int kThermalMeasurableXMin = 320;
constexpr int kThermalMeasurableXMax = 1279;
constexpr int kThermalMeasurableYMin = 32;
constexpr int kThermalMeasurableYMax = 1023;
constexpr double kAlarmLimitMinDegC = -100.0;
constexpr double kAlarmLimitMaxDegC = 500.0;
constexpr double kAlarmDifferenceMinDegC = 0.1;
constexpr double kAlarmDifferenceMaxDegC = 600.0;
constexpr int16_t kAlarmOffWire = -2732;  // "off" for every alarm limit
constexpr double kThresholdReferenceMinDegC = -30.0;
constexpr double kThresholdReferenceMaxDegC = 50.0;
constexpr double kThresholdFloatMaxDegC = 80.0;
constexpr double kThermalDeciDegMin = -3276.8;  // what int16 x0.1 degC can carry
constexpr double kThermalDeciDegMax = 3276.7;

// The three alarm limits (int16 x0.1 degC, -2732 = off): the same fields in 0x000124 and in the
// settings ACK 0x010100 (bytes 11..16).
template <class S, class V>
void thermal_alarm_limits(S& s, V& v) {
  constexpr auto limit =
      wire::or_off(wire::scaled<int16_t>(10).range(kAlarmLimitMinDegC, kAlarmLimitMaxDegC, "degC"),
                   kAlarmOffWire);
  constexpr auto difference = wire::or_off(
      wire::scaled<int16_t>(10).range(kAlarmDifferenceMinDegC, kAlarmDifferenceMaxDegC, "degC"),
      kAlarmOffWire);
  v("high_alarm",
    wire::switchable("high_alarm_on", s.high_alarm_on, "high_alarm_degC", s.high_alarm_degC),
    limit);
  v("low_alarm",
    wire::switchable("low_alarm_on", s.low_alarm_on, "low_alarm_degC", s.low_alarm_degC), limit);
  v("difference_alarm",
    wire::switchable("difference_alarm_on", s.difference_alarm_on, "difference_alarm_degC",
                     s.difference_alarm_degC),
    difference);
}

// The threshold alarm (switch byte, int16 x0.1 degC reference and float): the same fields in
// 0x000126 and in the settings ACK (bytes 17..21); `on` is how the switch byte is read.
template <class S, class V, class OnTag>
void thermal_threshold_alarm(S& s, V& v, OnTag on) {
  v("threshold_alarm_on", s.threshold_alarm_on, on);
  v("threshold_reference_degC", s.threshold_reference_degC,
    wire::scaled<int16_t>(10).range(kThresholdReferenceMinDegC, kThresholdReferenceMaxDegC,
                                    "degC"));
  v("threshold_float_degC", s.threshold_float_degC,
    wire::scaled<int16_t>(10).range(0.0, kThresholdFloatMaxDegC, "degC"));
}

}  // namespace k40t::protocol
