#include "k40t_driver/protocol/convention_readings.h"

#include <algorithm>
#include <cmath>

namespace k40t::protocol {

namespace {

// What an int16 x0.01 deg field decodes a uint16 above 32767 as: the value minus 655.36.
constexpr double kUint16CentiDegSpan = 655.36;

// A yaw decoded as int16 from a pod that sends a uint16 0..360 heading -> -180..180.
double heading_to_signed(double decoded) {
  double heading = decoded < 0 ? decoded + kUint16CentiDegSpan : decoded;
  return heading > 180.0 ? heading - 360.0 : heading;
}

// The inverse for the simulator: -180..180 -> 0..360, in the int16 field's bits.
double signed_to_heading_field(double yaw) {
  double heading = yaw < 0 ? yaw + 360.0 : yaw;
  if (heading >= 360.0) heading -= 360.0;
  return heading > GimbalAttitude::kCentiDegMax ? heading - kUint16CentiDegSpan : heading;
}

double roll_factor(const Conventions& c) {
  return c.roll_sign == RollSign::kRightDown ? 1.0 : -1.0;
}

void scale_signs(GimbalAttitude& m, const Conventions& c) {
  const double yaw = yaw_factor(c);
  const double pitch = pitch_factor(c);
  const double roll = roll_factor(c);
  m.joint_yaw_deg *= yaw;
  m.yaw_deg *= yaw;
  m.yaw_rate_deg_s *= yaw;
  m.joint_pitch_deg *= pitch;
  m.pitch_deg *= pitch;
  m.pitch_rate_deg_s *= pitch;
  m.joint_roll_deg *= roll;
  m.roll_deg *= roll;
  m.roll_rate_deg_s *= roll;
}

// The enhancement byte as the pod sent it (the layout splits it into bit 7 and bits 6..0).
uint8_t enhancement_byte(const ThermalSettingsAck& m) {
  return static_cast<uint8_t>((m.enhancement_on ? 0x80 : 0) | (m.enhancement_level & 0x7F));
}

uint8_t enhancement_level_of(uint8_t byte, EnhancementSwitch reading) {
  switch (reading) {
    case EnhancementSwitch::kBit7:
      return byte & 0x7F;
    case EnhancementSwitch::kBit0:
      return static_cast<uint8_t>(byte >> 1);
    case EnhancementSwitch::kLevel:
      return byte;
  }
  return byte;
}

constexpr int64_t kMsPerDay = 86400000;

int64_t wrap_day(int64_t ms) {
  return ((ms % kMsPerDay) + kMsPerDay) % kMsPerDay;
}

CodecOptions with_data_order(const CodecOptions& o) {
  CodecOptions data = o;
  if (o.conventions.gps_answer_byte_order == GpsAnswerByteOrder::kBig)
    data.ack_byte_order = ByteOrder::kBig;
  if (o.conventions.gps_answer_byte_order == GpsAnswerByteOrder::kLittle)
    data.ack_byte_order = ByteOrder::kLittle;
  return data;
}

}  // namespace

double yaw_factor(const Conventions& c) {
  return c.yaw_sign == YawSign::kRight ? 1.0 : -1.0;
}

double pitch_factor(const Conventions& c) {
  return c.pitch_sign == PitchSign::kUp ? 1.0 : -1.0;
}

void attitude_from_wire(GimbalAttitude& m, const Conventions& c, YawRange range) {
  if (range == YawRange::kHeading) {
    m.joint_yaw_deg = heading_to_signed(m.joint_yaw_deg);
    m.yaw_deg = heading_to_signed(m.yaw_deg);
  }
  scale_signs(m, c);
}

void attitude_to_wire(GimbalAttitude& m, const Conventions& c) {
  scale_signs(m, c);  // its own inverse
  if (c.yaw_range == YawRange::kHeading) {
    m.joint_yaw_deg = signed_to_heading_field(m.joint_yaw_deg);
    m.yaw_deg = signed_to_heading_field(m.yaw_deg);
  }
}

YawRange yaw_range_evidence(const GimbalAttitude& as_decoded) {
  YawRange seen = YawRange::kAuto;
  for (const double yaw : {as_decoded.joint_yaw_deg, as_decoded.yaw_deg}) {
    if (yaw > 180.0 || yaw < -180.0) return YawRange::kHeading;
    if (yaw < 0) seen = YawRange::kSigned;
  }
  return seen;
}

void sd_capacities_from_wire(CameraSystemStatus& m, const Conventions& c) {
  if (c.sd_capacity_unit == SdCapacityUnit::k10Mb) return;
  const double factor = 0.1 / kSdCapacityUnitMb;  // counts of 0.1 MB read as counts of 10 MB
  m.sd_total_mb *= factor;
  m.sd_free_mb *= factor;
  m.sd_used_mb *= factor;
}

double sd_capacity_to_wire(double true_mb, const Conventions& c) {
  const double unit_mb = c.sd_capacity_unit == SdCapacityUnit::k10Mb ? kSdCapacityUnitMb : 0.1;
  // Round down, so used + free never exceeds total; a reading that cannot carry the card
  // saturates, as a 16-bit field must.
  const double counts = std::min(std::floor(true_mb / unit_mb + 1e-9), 65535.0);
  return counts * kSdCapacityUnitMb;
}

double shutter_us_from_wire(uint16_t raw, ShutterField field) {
  switch (field) {
    case ShutterField::kMicroseconds:
      return raw;
    case ShutterField::kHundredMicroseconds:
      return raw * 100.0;
    case ShutterField::kMicrosecondsWrapped: {
      // The camera's shutters beyond 16 bits (section 3.2.3.5): 1/4, 1/8, 1/15 s. A raw value
      // that is one of them less a multiple of 65536 is that shutter.
      for (const double slow_us : {250000.0, 125000.0, 1e6 / 15}) {
        const double wrapped = std::fmod(std::round(slow_us), 65536.0);
        if (std::abs(raw - wrapped) <= 1.0) return std::round(slow_us);
      }
      return raw;
    }
  }
  return raw;
}

uint16_t shutter_to_wire(double true_us, ShutterField field) {
  const double us = std::max(0.0, std::round(true_us));
  switch (field) {
    case ShutterField::kMicroseconds:
      return static_cast<uint16_t>(std::min(us, 65535.0));
    case ShutterField::kMicrosecondsWrapped:
      return static_cast<uint16_t>(static_cast<uint64_t>(us) & 0xFFFF);
    case ShutterField::kHundredMicroseconds:
      return static_cast<uint16_t>(std::min(std::round(us / 100.0), 65535.0));
  }
  return 0;
}

Enhancement enhancement_from_wire(const ThermalSettingsAck& m, EnhancementSwitch reading) {
  const uint8_t byte = enhancement_byte(m);
  Enhancement e;
  e.level = enhancement_level_of(byte, reading);
  const bool switch_bit = reading == EnhancementSwitch::kBit7   ? (byte & 0x80) != 0
                          : reading == EnhancementSwitch::kBit0 ? (byte & 0x01) != 0
                                                                : false;
  e.on = switch_bit || e.level > 0;  // decision T7: a level is on even with its switch clear
  return e;
}

void enhancement_to_wire(ThermalSettingsAck& m, uint8_t level, EnhancementSwitch reading) {
  const bool on = level > 0;
  uint8_t byte = level;
  if (reading == EnhancementSwitch::kBit7) byte = static_cast<uint8_t>((on ? 0x80 : 0) | level);
  if (reading == EnhancementSwitch::kBit0) byte = static_cast<uint8_t>((level << 1) | (on ? 1 : 0));
  m.enhancement_on = (byte & 0x80) != 0;
  m.enhancement_level = byte & 0x7F;
}

bool enhancement_fits(const ThermalSettingsAck& m, EnhancementSwitch reading) {
  return enhancement_level_of(enhancement_byte(m), reading) <= kThermalEnhancementMax;
}

uint8_t thermal_zoom_from_wire(uint8_t code, ThermalZoomCode reading) {
  return reading == ThermalZoomCode::kZeroBased ? static_cast<uint8_t>(code + 1) : code;
}

uint8_t thermal_zoom_to_wire(uint8_t ratio, ThermalZoomCode reading) {
  return reading == ThermalZoomCode::kZeroBased ? static_cast<uint8_t>(ratio - 1) : ratio;
}

bool thermal_zoom_fits(uint8_t code, ThermalZoomCode reading) {
  const int ratio = thermal_zoom_from_wire(code, reading);
  return ratio >= kThermalZoomMin && ratio <= kThermalZoomMax;
}

int64_t gps_request_utc_ms_of_day(const CameraGpsRequest& m, GpsRequestTime reading,
                                  int minutes_west) {
  const int64_t of_day = ((m.hour * 60 + m.minute) * 60 + m.second) * int64_t{1000} + m.millisecond;
  if (reading == GpsRequestTime::kUtc) return of_day;
  return wrap_day(of_day + int64_t{minutes_west} * 60000);  // struct timezone: UTC = local + west
}

void gps_request_time_to_wire(CameraGpsRequest& m, int64_t utc_ms_of_day, GpsRequestTime reading,
                              int minutes_west) {
  int64_t ms = wrap_day(utc_ms_of_day);
  if (reading == GpsRequestTime::kLocal) ms = wrap_day(ms - int64_t{minutes_west} * 60000);
  m.millisecond = static_cast<uint16_t>(ms % 1000);
  m.second = static_cast<uint8_t>(ms / 1000 % 60);
  m.minute = static_cast<uint8_t>(ms / 60000 % 60);
  m.hour = static_cast<uint8_t>(ms / 3600000);
}

Result<Payload> encode_gps_answer(const CameraGpsAck& m, const CodecOptions& o) {
  Result<Payload> payload = encode_payload(m, with_data_order(o));
  if (!payload) return payload;
  // The response code keeps ack_byte_order (docs/protocol/decisions.md#a2).
  const auto code = static_cast<uint16_t>(m.code);
  const bool big = o.ack_byte_order == ByteOrder::kBig;
  payload->bytes[0] = static_cast<uint8_t>(big ? code >> 8 : code & 0xFF);
  payload->bytes[1] = static_cast<uint8_t>(big ? code & 0xFF : code >> 8);
  return payload;
}

Result<CameraGpsAck> decode_gps_answer(const uint8_t* data, size_t size, const CodecOptions& o) {
  Result<CameraGpsAck> ack = decode_payload<CameraGpsAck>(data, size, with_data_order(o));
  if (!ack || size < 2) return ack;
  const bool big = o.ack_byte_order == ByteOrder::kBig;
  ack->code = static_cast<ResponseCode>(big ? (data[0] << 8) | data[1] : (data[1] << 8) | data[0]);
  return ack;
}

bool laser_target_no_return(const TargetGpsAck& m, LaserTargetZeros reading) {
  return reading == LaserTargetZeros::kNoReturn && m.code == ResponseCode::kOk &&
         m.latitude_deg == 0.0 && m.longitude_deg == 0.0;
}

FocusCommand manual_focus_command(bool nearer, FocusPlus reading) {
  const bool plus = nearer == (reading == FocusPlus::kNear);
  return plus ? FocusCommand::kFinePlus : FocusCommand::kFineMinus;
}

bool manual_focus_is_nearer(FocusCommand command, FocusPlus reading) {
  return (command == FocusCommand::kFinePlus) == (reading == FocusPlus::kNear);
}

}  // namespace k40t::protocol
