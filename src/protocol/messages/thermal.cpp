#include "k40t_driver/protocol/messages/thermal.h"

#include <string>

#include "setting_bytes.h"

namespace k40t::protocol {

using detail::check_level;
using detail::code_of;
using detail::read_switch;

const char* to_string(Palette palette) {
  switch (palette) {
    case Palette::kWhiteHot:
      return "white_hot";
    case Palette::kBlackHot:
      return "black_hot";
    case Palette::kRainbow:
      return "rainbow";
    case Palette::kHighContrastRainbow:
      return "high_contrast_rainbow";
    case Palette::kIronRed:
      return "iron_red";
    case Palette::kMagma:
      return "magma";
    case Palette::kSky:
      return "sky";
    case Palette::kMediumGrey:
      return "medium_grey";
    case Palette::kGreyRed:
      return "grey_red";
    case Palette::kPurpleOrange:
      return "purple_orange";
    case Palette::kSpecial1:
      return "special_1";
    case Palette::kWarningRed:
      return "warning_red";
    case Palette::kIceFire:
      return "ice_fire";
    case Palette::kCyanRed:
      return "cyan_red";
    case Palette::kSpecial2:
      return "special_2";
    case Palette::kGradientRed:
      return "gradient_red";
    case Palette::kGradientGreen:
      return "gradient_green";
    case Palette::kGradientYellow:
      return "gradient_yellow";
    case Palette::kWarningGreen:
      return "warning_green";
    case Palette::kWarningBlue:
      return "warning_blue";
  }
  return nullptr;
}

const char* to_string(ThermalGainMode mode) {
  switch (mode) {
    case ThermalGainMode::kHigh:
      return "high";
    case ThermalGainMode::kLow:
      return "low";
    case ThermalGainMode::kAuto:
      return "auto";
  }
  return nullptr;
}

const char* to_string(ThermalMeasurementType type) {
  switch (type) {
    case ThermalMeasurementType::kPoint:
      return "point";
    case ThermalMeasurementType::kArea:
      return "area";
  }
  return nullptr;
}

const char* to_string(ThermalCoreType type) {
  switch (type) {
    case ThermalCoreType::kSighting:
      return "sighting";
    case ThermalCoreType::kRadiometric:
      return "radiometric";
  }
  return nullptr;
}

namespace {

constexpr double kDeciDegMax = 3276.7;  // int16 / 10
constexpr double kDeciDegMin = -3276.8;
constexpr uint8_t kMeasurementOnWire = 0x00;  // 3.2.2.4: 0 = on, 1 = off
constexpr uint8_t kMeasurementOffWire = 0x01;

// ---- alarm limits: the same three int16 in 0x000124 and in the 0x010100 ACK (bytes 11..16) ----
int16_t alarm_to_wire(bool on, double degC) {
  return on ? to_wire<int16_t>(degC, 10) : kAlarmOffWire;
}
void alarm_from_wire(int16_t raw, bool* on, double* degC) {
  *on = raw != kAlarmOffWire;
  *degC = *on ? raw / 10.0 : 0.0;
}
Status check_alarm(const char* field, bool on, double degC, double lo, double hi) {
  return on ? check_range(field, degC, lo, hi, "degC") : Status::ok();
}

template <class T>
Status check_alarm_limits(const T& m) {
  return first_failure(
      check_alarm("high_alarm_degC", m.high_alarm_on, m.high_alarm_degC, kAlarmLimitMinDegC,
                  kAlarmLimitMaxDegC),
      check_alarm("low_alarm_degC", m.low_alarm_on, m.low_alarm_degC, kAlarmLimitMinDegC,
                  kAlarmLimitMaxDegC),
      check_alarm("difference_alarm_degC", m.difference_alarm_on, m.difference_alarm_degC,
                  kAlarmDifferenceMinDegC, kAlarmDifferenceMaxDegC));
}
template <class T>
void write_alarm_limits(ByteWriter& w, const T& m, ByteOrder order) {
  w.i16(alarm_to_wire(m.high_alarm_on, m.high_alarm_degC), order);
  w.i16(alarm_to_wire(m.low_alarm_on, m.low_alarm_degC), order);
  w.i16(alarm_to_wire(m.difference_alarm_on, m.difference_alarm_degC), order);
}
template <class T>
void read_alarm_limits(ByteReader& r, T* m, ByteOrder order) {
  alarm_from_wire(r.i16(order), &m->high_alarm_on, &m->high_alarm_degC);
  alarm_from_wire(r.i16(order), &m->low_alarm_on, &m->low_alarm_degC);
  alarm_from_wire(r.i16(order), &m->difference_alarm_on, &m->difference_alarm_degC);
}

// ---- threshold alarm: switch byte + two int16, in 0x000126 and in the ACK (bytes 17..21) ----
template <class T>
Status check_threshold(const T& m) {
  return first_failure(check_range("threshold_reference_degC", m.threshold_reference_degC,
                                   kThresholdReferenceMinDegC, kThresholdReferenceMaxDegC, "degC"),
                       check_range("threshold_float_degC", m.threshold_float_degC, 0.0,
                                   kThresholdFloatMaxDegC, "degC"));
}
template <class T>
void write_threshold(ByteWriter& w, const T& m, ByteOrder order) {
  w.u8(m.threshold_alarm_on ? 1 : 0);
  w.i16(to_wire<int16_t>(m.threshold_reference_degC, 10), order);
  w.i16(to_wire<int16_t>(m.threshold_float_degC, 10), order);
}
template <class T>
void read_threshold_values(ByteReader& r, T* m, ByteOrder order) {
  m->threshold_reference_degC = r.i16(order) / 10.0;
  m->threshold_float_degC = r.i16(order) / 10.0;
}

}  // namespace

// ---- 0x000004 ------------------------------------------------------------------------------
Status ThermalStatus::validate() const {
  return first_failure(check_range("max_degC", max_degC, kDeciDegMin, kDeciDegMax, "degC"),
                       check_range("min_degC", min_degC, kDeciDegMin, kDeciDegMax, "degC"),
                       check_range("center_degC", center_degC, kDeciDegMin, kDeciDegMax, "degC"),
                       check_range("point_degC", point_degC, kDeciDegMin, kDeciDegMax, "degC"),
                       check_range("average_degC", average_degC, kDeciDegMin, kDeciDegMax, "degC"));
}

void ThermalStatus::encode(ByteWriter& w, const CodecOptions&) const {
  for (double v : {max_degC, min_degC, center_degC, point_degC, average_degC}) {
    w.i16(to_wire<int16_t>(v, 10));
  }
  for (uint16_t v :
       {max_x_px, max_y_px, min_x_px, min_y_px, center_x_px, center_y_px, point_x_px, point_y_px}) {
    w.u16(v);
  }
  for (bool v : {high_alarm, low_alarm, difference_alarm, threshold_alarm}) w.u8(v ? 1 : 0);
  w.zeros(4);
}

Status ThermalStatus::decode(ByteReader& r, const CodecOptions&) {
  for (double* v : {&max_degC, &min_degC, &center_degC, &point_degC, &average_degC}) {
    *v = r.i16() / 10.0;
  }
  for (uint16_t* v : {&max_x_px, &max_y_px, &min_x_px, &min_y_px, &center_x_px, &center_y_px,
                      &point_x_px, &point_y_px}) {
    *v = r.u16();
  }
  // A report is what the pod says: any non-zero flag byte counts as "alarm".
  for (bool* v : {&high_alarm, &low_alarm, &difference_alarm, &threshold_alarm}) *v = r.u8() != 0;
  return Status::ok();
}

// ---- 0x010100 ------------------------------------------------------------------------------
Status ThermalSettingsAck::validate() const {
  return first_failure(
      check_enum("palette", palette), check_enum("measurement_type", measurement_type),
      check_enum("core_type", core_type),
      check_level("zoom_x", zoom_x, kThermalZoomMin, kThermalZoomMax),
      check_level("sharpness", sharpness, 0, kThermalLevelMax), check_enum("gain_mode", gain_mode),
      check_level("brightness", brightness, 0, kThermalLevelMax),
      check_level("contrast", contrast, 0, kThermalLevelMax),
      check_level("denoise_level", denoise_level, 0, kThermalLevelMax),
      check_level("enhancement_level", enhancement_level, 0, kThermalEnhancementMax),
      check_alarm_limits(*this), check_threshold(*this));
}

void ThermalSettingsAck::encode(ByteWriter& w, const CodecOptions& o) const {
  w.u16(static_cast<uint16_t>(code), o.ack_byte_order);
  w.u8(code_of(palette));
  w.u8(static_cast<uint8_t>((measurement_on ? kMeasurementOnWire : kMeasurementOffWire) |
                            (code_of(measurement_type) << 1) | (code_of(core_type) << 2) |
                            (zoom_x << 3)));
  w.u8(sharpness);
  w.u8(code_of(gain_mode));
  w.u8(brightness);
  w.u8(contrast);
  w.u8(detail::pack_switch_and_level(denoise_on, denoise_level));
  w.u8(detail::pack_switch_and_level(enhancement_on, enhancement_level));
  write_alarm_limits(w, *this, o.ack_byte_order);
  write_threshold(w, *this, o.ack_byte_order);
  w.zeros(2);
}

Status ThermalSettingsAck::decode(ByteReader& r, const CodecOptions& o) {
  code = static_cast<ResponseCode>(r.u16(o.ack_byte_order));
  bool has_settings = false;
  const Status follow = detail::settings_follow(r, code, kSettingsMinSize, &has_settings);
  if (!follow || !has_settings) return follow;
  palette = static_cast<Palette>(r.u8());
  const uint8_t config = r.u8();
  measurement_on = (config & 0x01) == kMeasurementOnWire;
  measurement_type = static_cast<ThermalMeasurementType>((config >> 1) & 0x01);
  core_type = static_cast<ThermalCoreType>((config >> 2) & 0x01);
  zoom_x = static_cast<uint8_t>(config >> 3);
  sharpness = r.u8();
  gain_mode = static_cast<ThermalGainMode>(r.u8());
  brightness = r.u8();
  contrast = r.u8();
  detail::unpack_switch_and_level(r.u8(), &denoise_on, &denoise_level);
  detail::unpack_switch_and_level(r.u8(), &enhancement_on, &enhancement_level);
  read_alarm_limits(r, this, o.ack_byte_order);
  threshold_alarm_on = r.u8() != 0;
  read_threshold_values(r, this, o.ack_byte_order);
  return Status::ok();
}

// ---- 0x00010D ------------------------------------------------------------------------------
Status ThermalDenoiseRequest::validate() const {
  return check_level("denoise_level", denoise_level, 0, kThermalLevelMax);
}
void ThermalDenoiseRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.u8(denoise_on ? 1 : 0);
  w.u8(denoise_level);
  w.zeros(1);
}
Status ThermalDenoiseRequest::decode(ByteReader& r, const CodecOptions&) {
  const Status on = read_switch(r, "denoise_on", 1, 0, &denoise_on);
  denoise_level = r.u8();
  return on;
}

// ---- 0x00010F ------------------------------------------------------------------------------
Status ThermalSpotRequest::validate() const {
  return first_failure(check_level("x_px", x_px, 0, kThermalPictureWidth),
                       check_level("y_px", y_px, 0, kThermalPictureHeight));
}
void ThermalSpotRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.u16(x_px);
  w.u16(y_px);
  w.zeros(1);
}
Status ThermalSpotRequest::decode(ByteReader& r, const CodecOptions&) {
  x_px = r.u16();
  y_px = r.u16();
  return Status::ok();
}

// ---- 0x000110 ------------------------------------------------------------------------------
namespace {
// centre -+ size/2 must stay inside lo..hi. Integer halves, as the pod's C code would compute
// "half the width" (a 1-pixel rectangle on the edge is inside).
Status check_span(const char* size_field, const char* center_field, const char* axis, int64_t size,
                  int64_t center, int64_t lo, int64_t hi) {
  const int64_t first = center - size / 2;
  const int64_t last = center + size / 2;
  if (first >= lo && last <= hi) return Status::ok();
  return Status::fail(std::string("fields '") + size_field + "' and '" + center_field +
                      "' put the rectangle at " + axis + " " + std::to_string(first) + ".." +
                      std::to_string(last) + ", outside the measurable area " + axis + " " +
                      std::to_string(lo) + ".." + std::to_string(hi) + " (section 3.2.2.11)");
}
}  // namespace

Status ThermalAreaRequest::validate() const {
  return first_failure(
      check_level("width_px", width_px, 1, kThermalMeasurableXMax - kThermalMeasurableXMin),
      check_level("height_px", height_px, 1, kThermalMeasurableYMax - kThermalMeasurableYMin),
      check_level("center_x_px", center_x_px, kThermalMeasurableXMin, kThermalMeasurableXMax),
      check_level("center_y_px", center_y_px, kThermalMeasurableYMin, kThermalMeasurableYMax),
      check_span("width_px", "center_x_px", "x", width_px, center_x_px, kThermalMeasurableXMin,
                 kThermalMeasurableXMax),
      check_span("height_px", "center_y_px", "y", height_px, center_y_px, kThermalMeasurableYMin,
                 kThermalMeasurableYMax));
}
void ThermalAreaRequest::encode(ByteWriter& w, const CodecOptions&) const {
  for (uint16_t v : {width_px, height_px, center_x_px, center_y_px}) w.u16(v);
  w.zeros(1);
}
Status ThermalAreaRequest::decode(ByteReader& r, const CodecOptions&) {
  for (uint16_t* v : {&width_px, &height_px, &center_x_px, &center_y_px}) *v = r.u16();
  return Status::ok();
}

// ---- 0x000124 ------------------------------------------------------------------------------
Status ThermalAlarmsRequest::validate() const {
  return check_alarm_limits(*this);
}
void ThermalAlarmsRequest::encode(ByteWriter& w, const CodecOptions&) const {
  write_alarm_limits(w, *this, ByteOrder::kLittle);
  w.zeros(2);
}
Status ThermalAlarmsRequest::decode(ByteReader& r, const CodecOptions&) {
  read_alarm_limits(r, this, ByteOrder::kLittle);
  return Status::ok();
}

// ---- 0x000126 ------------------------------------------------------------------------------
Status ThermalThresholdAlarmRequest::validate() const {
  return check_threshold(*this);
}
void ThermalThresholdAlarmRequest::encode(ByteWriter& w, const CodecOptions&) const {
  write_threshold(w, *this, ByteOrder::kLittle);
  w.zeros(1);
}
Status ThermalThresholdAlarmRequest::decode(ByteReader& r, const CodecOptions&) {
  const Status on = read_switch(r, "threshold_alarm_on", 1, 0, &threshold_alarm_on);
  read_threshold_values(r, this, ByteOrder::kLittle);
  return on;
}

}  // namespace k40t::protocol
