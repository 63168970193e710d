#include "k40t_driver/protocol/conventions.h"

#include <cerrno>
#include <cstdlib>

namespace k40t::protocol {
namespace {

Status bad_value(const ConventionInfo& info, const std::string& text) {
  return Status::fail(std::string(info.name) + " must be " + convention_values_text(info) +
                      ", got '" + text + "'");
}

// The index of `text` in the entry's value list, or -1.
int value_index(const ConventionInfo& info, const std::string& text) {
  for (size_t i = 0; i < info.values.size(); ++i)
    if (text == info.values[i]) return static_cast<int>(i);
  return -1;
}

// A reading of Conventions whose enum values follow the table's value list.
template <class E, E Conventions::*Member>
Status set_enum(const ConventionInfo& info, ConventionRefs refs, const std::string& text) {
  const int i = value_index(info, text);
  if (i < 0) return bad_value(info, text);
  refs.codec.conventions.*Member = static_cast<E>(i);
  return Status::ok();
}

template <class E, E Conventions::*Member>
std::string get_enum(const ConventionInfo& info, ConstConventionRefs refs) {
  return info.values.at(static_cast<size_t>(refs.codec.conventions.*Member));
}

// The byte orders of CodecOptions, written "big" / "little".
template <ByteOrder CodecOptions::*Member>
Status set_order(const ConventionInfo& info, ConventionRefs refs, const std::string& text) {
  Result<ByteOrder> order = parse_byte_order(text);
  if (!order) return bad_value(info, text);
  refs.codec.*Member = *order;
  return Status::ok();
}

template <ByteOrder CodecOptions::*Member>
std::string get_order(const ConventionInfo&, ConstConventionRefs refs) {
  return to_string(refs.codec.*Member);
}

Status set_ack_order(const ConventionInfo& info, ConventionRefs refs, const std::string& text) {
  return parse_ack_byte_order(text, refs.codec) ? Status::ok() : bad_value(info, text);
}

std::string get_ack_order(const ConventionInfo&, ConstConventionRefs refs) {
  return refs.codec.ack_byte_order_auto ? "auto" : to_string(refs.codec.ack_byte_order);
}

Status set_crc(const ConventionInfo& info, ConventionRefs refs, const std::string& text) {
  Result<CrcCoverage> coverage = parse_crc_coverage(text);
  if (!coverage) return bad_value(info, text);
  refs.crc_coverage = *coverage;
  return Status::ok();
}

std::string get_crc(const ConventionInfo&, ConstConventionRefs refs) {
  return to_string(refs.crc_coverage);
}

// A whole decimal number within lo..hi, or a message.
Result<long> parse_number(const ConventionInfo& info, const std::string& text, long lo, long hi) {
  errno = 0;
  char* end = nullptr;
  const long v = text.empty() ? 0 : std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < lo || v > hi)
    return Result<long>::fail(std::string(info.name) + " must be a whole number " +
                              info.number_range + ", got '" + text + "'");
  return v;
}

Status set_scale(const ConventionInfo& info, ConventionRefs refs, const std::string& text) {
  Result<long> v = parse_number(info, text, 1, kMaxAngleCommandScale);
  if (!v) return v.status();
  refs.codec.angle_command_scale = static_cast<int>(*v);
  return Status::ok();
}

std::string get_scale(const ConventionInfo&, ConstConventionRefs refs) {
  return std::to_string(refs.codec.angle_command_scale);
}

template <Address CodecOptions::*Member>
Status set_system(const ConventionInfo& info, ConventionRefs refs, const std::string& text) {
  Result<long> v = parse_number(info, text, 0, 255);
  if (!v) return v.status();
  (refs.codec.*Member).system = static_cast<uint8_t>(*v);
  return Status::ok();
}

template <Address CodecOptions::*Member>
std::string get_system(const ConventionInfo&, ConstConventionRefs refs) {
  return std::to_string((refs.codec.*Member).system);
}

#define K40T_ENUM_ACCESS(Type, member) \
  &set_enum<Type, &Conventions::member>, &get_enum<Type, &Conventions::member>

const std::vector<ConventionInfo> kTable = {
    {"crc_coverage",
     "2.1",
     {"auto", "header_excluded", "whole_frame"},
     nullptr,
     "auto",
     "which bytes the checksum covers (decisions.md#a1)",
     &set_crc,
     &get_crc,
     true},
    {"ack_byte_order",
     "2.1 note",
     {"big", "little", "auto"},
     nullptr,
     "big",
     "byte order of ACK fields, response codes included (decisions.md#a2)",
     &set_ack_order,
     &get_ack_order,
     true},
    {"laser_status_byte_order",
     "3.2.5.2 (0x020406)",
     {"little", "big"},
     nullptr,
     "little",
     "byte order of the periodic laser range 0x020406",
     &set_order<&CodecOptions::laser_status_byte_order>,
     &get_order<&CodecOptions::laser_status_byte_order>,
     false},
    {"angle_command_scale",
     "3.1.2.2 (0x000012)",
     {},
     "1..364",
     "100",
     "0x000012's angle magnitudes are degrees x this (decisions.md#a4)",
     &set_scale,
     &get_scale,
     true},
    {"gimbal_system_id",
     "3.1 against 2.1",
     {},
     "0..255",
     "3",
     "system id gimbal requests go to (decisions.md#a3)",
     &set_system<&CodecOptions::gimbal_address>,
     &get_system<&CodecOptions::gimbal_address>,
     false},
    {"camera_system_id",
     "3.2 against 2.1",
     {},
     "0..255",
     "4",
     "system id camera and laser requests go to (decisions.md#a3)",
     &set_system<&CodecOptions::camera_address>,
     &get_system<&CodecOptions::camera_address>,
     false},
    {"yaw_sign",
     "3.1.1.2 (0x000002)",
     {"right", "left"},
     nullptr,
     "right",
     "a positive 0x000002 yaw (joint, attitude, rate) turns right, clockwise seen from above",
     K40T_ENUM_ACCESS(YawSign, yaw_sign),
     true},
    {"pitch_sign",
     "3.1.1.2 (0x000002)",
     {"up", "down"},
     nullptr,
     "up",
     "a positive 0x000002 pitch (joint, attitude, rate) looks up",
     K40T_ENUM_ACCESS(PitchSign, pitch_sign),
     true},
    {"roll_sign",
     "3.1.1.2 (0x000002)",
     {"right_down", "left_down"},
     nullptr,
     "right_down",
     "a positive 0x000002 roll (joint, attitude, rate) lowers the right side",
     K40T_ENUM_ACCESS(RollSign, roll_sign),
     false},
    {"attitude_order",
     "3.1.1.2 (0x000002 bytes 7-12)",
     {"zyx", "zxy"},
     nullptr,
     "zyx",
     "the attitude angles compose yaw-pitch-roll (zyx) or like the joints yaw-roll-pitch (zxy)",
     K40T_ENUM_ACCESS(AttitudeOrder, attitude_order),
     false},
    {"yaw_range",
     "3.1.1.2 (0x000002)",
     {"auto", "signed", "heading"},
     nullptr,
     "auto",
     "0x000002 yaw is int16 +-180 deg or a uint16 0..360 heading (auto: from the values seen)",
     K40T_ENUM_ACCESS(YawRange, yaw_range),
     true},
    {"sd_capacity_unit",
     "3.2.1.1 (0x000003 bytes 10-15)",
     {"10mb", "0.1mb"},
     nullptr,
     "10mb",
     "one count of the SD capacities \"MB*10\" is 10 MB or 0.1 MB",
     K40T_ENUM_ACCESS(SdCapacityUnit, sd_capacity_unit),
     false},
    {"shutter_field",
     "3.2.1.3 (0x000005 bytes 9-10)",
     {"us", "us_wrapped", "100us"},
     nullptr,
     "us",
     "shutter in us saturating at 65535, us wrapped to 16 bits, or counts of 100 us",
     K40T_ENUM_ACCESS(ShutterField, shutter_field),
     true},
    {"enhancement_switch",
     "3.2.2.1 (ACK 0x010100 byte 10)",
     {"bit7", "bit0", "level"},
     nullptr,
     "bit7",
     "thermal enhancement switch in bit 7 (level 6..0), bit 0 (level 7..1) or none",
     K40T_ENUM_ACCESS(EnhancementSwitch, enhancement_switch),
     true},
    {"thermal_zoom_code",
     "3.2.2.1 (ACK 0x010100 byte 4 bits 3-7)",
     {"ratio", "zero_based"},
     nullptr,
     "ratio",
     "thermal zoom code is the ratio (1 = none) or the ratio - 1 (0 = none)",
     K40T_ENUM_ACCESS(ThermalZoomCode, thermal_zoom_code),
     true},
    {"calibration_end",
     "3.1.2.3/3.1.2.8/3.1.2.11 (0x000013/2E/31)",
     {"auto", "status", "ack"},
     nullptr,
     "auto",
     "a gimbal calibration ends with 0x000008 (status), with its OK ACK (ack), or either (auto)",
     K40T_ENUM_ACCESS(CalibrationEnd, calibration_end),
     true},
    {"photo_mode_2",
     "3.2.4.2 (0x000301 mode 2)",
     {"time_lapse", "self_timer"},
     nullptr,
     "time_lapse",
     "photo mode 2 repeats every interval until stopped, or shoots once after it",
     K40T_ENUM_ACCESS(PhotoMode2, photo_mode_2),
     false},
    {"gps_request_time",
     "3.2.4.15 (0x000310)",
     {"utc", "local"},
     nullptr,
     "utc",
     "the time of day in the pod's GPS request is UTC or local (time_zone_minutes_west)",
     K40T_ENUM_ACCESS(GpsRequestTime, gps_request_time),
     false},
    {"gps_answer_byte_order",
     "3.2.4.15 (ACK 0x010310)",
     {"ack", "big", "little"},
     nullptr,
     "ack",
     "byte order of 0x010310's data after its response code (ack: like ack_byte_order)",
     K40T_ENUM_ACCESS(GpsAnswerByteOrder, gps_answer_byte_order),
     false},
    {"laser_target_zeros",
     "3.2.4.24 (ACK 0x010320)",
     {"no_return", "position"},
     nullptr,
     "no_return",
     "an OK 0x010320 at latitude 0, longitude 0 means no laser return, or a position",
     K40T_ENUM_ACCESS(LaserTargetZeros, laser_target_zeros),
     false},
    {"focus_plus",
     "3.2.4.18 (0x000313 codes 1/2)",
     {"near", "far"},
     nullptr,
     "near",
     "manual focus code 1 (\"+\") focuses nearer (code 2 farther), or the other way",
     K40T_ENUM_ACCESS(FocusPlus, focus_plus),
     false},
};

#undef K40T_ENUM_ACCESS

}  // namespace

const std::vector<ConventionInfo>& convention_table() {
  return kTable;
}

const ConventionInfo* find_convention(const std::string& name) {
  for (const ConventionInfo& info : kTable)
    if (name == info.name) return &info;
  return nullptr;
}

std::string convention_values_text(const ConventionInfo& info) {
  if (info.values.empty()) return info.number_range ? info.number_range : "";
  std::string text;
  for (size_t i = 0; i < info.values.size(); ++i) {
    if (i > 0) text += i + 1 == info.values.size() ? " or " : ", ";
    text += info.values[i];
  }
  return text;
}

Status set_convention(ConventionRefs refs, const std::string& name, const std::string& value) {
  const ConventionInfo* info = find_convention(name);
  if (!info) {
    std::string names;
    for (const ConventionInfo& i : kTable) names += std::string(names.empty() ? "" : ", ") + i.name;
    return Status::fail("no convention named '" + name + "' (known: " + names + ")");
  }
  return info->set(*info, refs, value);
}

Status set_convention_assignment(ConventionRefs refs, const std::string& name_equals_value) {
  const size_t eq = name_equals_value.find('=');
  if (eq == std::string::npos)
    return Status::fail("a convention is NAME=VALUE, got '" + name_equals_value + "'");
  return set_convention(refs, name_equals_value.substr(0, eq), name_equals_value.substr(eq + 1));
}

}  // namespace k40t::protocol
