// The readings of the protocol document that it leaves open ("conventions"), one parameter each:
// docs/protocol/decisions.md#conventions lists them with their section, values, default and why.
//
// One NAME per reading is the ROS parameter (in the driver's private namespace, also loaded from a
// YAML file with `conventions:=FILE.yaml`), the simulator's `--convention NAME=VALUE` and the key
// `k40t probe` writes. Values are short snake_case words; `auto` (where listed) means "the default
// until the pod's frames show which one, then that" (see driver/convention_tracker.h).
//
// The readings that existed before this list stay where they were (crc_coverage in
// session::SessionOptions, the others in CodecOptions); the table reaches them through
// ConventionRefs so that one loop can parse, print or write every reading.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::protocol {

// Every enum's values are in the order of its names in the table (convention_table()).

// 0x000002 (3.1.1.2): which way a positive yaw, pitch and roll turn. The joint and the attitude
// angles and their rates share one sign each.
enum class YawSign : uint8_t { kRight, kLeft };           // "right" (clockwise from above) | "left"
enum class PitchSign : uint8_t { kUp, kDown };            // "up" | "down"
enum class RollSign : uint8_t { kRightDown, kLeftDown };  // "right_down" | "left_down"
// 0x000002 bytes 7-12: the order the attitude angles compose in (intrinsic).
enum class AttitudeOrder : uint8_t {
  kZyx,
  kZxy
};  // "zyx" (yaw, pitch, roll) | "zxy" (the joints')
// 0x000002 yaw bytes: int16 degrees x100 (+-180) or uint16 0..360 heading.
enum class YawRange : uint8_t { kAuto, kSigned, kHeading };  // "auto" | "signed" | "heading"
// 0x000003 bytes 10-15 "MB*10": one count is 10 MB or 0.1 MB.
enum class SdCapacityUnit : uint8_t { k10Mb, kTenthMb };  // "10mb" | "0.1mb"
// 0x000005 bytes 9-10 "microseconds" in 16 bits, which cannot carry 1/4, 1/8, 1/15 s.
enum class ShutterField : uint8_t {
  kMicroseconds,         // "us": microseconds, slower shutters saturate at 65535
  kMicrosecondsWrapped,  // "us_wrapped": the low 16 bits of the microseconds
  kHundredMicroseconds,  // "100us": one count is 100 us
};
// ACK 0x010100 byte 10 (3.2.2.1): where the enhancement switch is (decision T7).
enum class EnhancementSwitch : uint8_t {
  kBit7,   // "bit7": bit 7 switch, bits 6..0 level (like byte 9)
  kBit0,   // "bit0": bit 0 switch (as written), bits 7..1 level
  kLevel,  // "level": no switch bit, the byte is the level and level > 0 is on
};
// ACK 0x010100 byte 4 bits 3-7 "electronic zoom".
enum class ThermalZoomCode : uint8_t { kRatio, kZeroBased };  // "ratio" (1 = none) | "zero_based"
// How a gimbal calibration (0x000013, 0x00002E, 0x000031) tells it has ended.
enum class CalibrationEnd : uint8_t {
  kAuto,    // "auto": 0x000008 if it reports "repairing" soon after the OK ACK, else the ACK
  kStatus,  // "status": 0x000008 "repairing" then "succeeded"/"failed"
  kAck,     // "ack": the OK ACK itself is the end
};
// 0x000301 photo mode 2 "延时拍照".
enum class PhotoMode2 : uint8_t { kTimeLapse, kSelfTimer };  // "time_lapse" | "self_timer"
// 0x000310's hour/minute/second/ms: the time of day of the photo.
enum class GpsRequestTime : uint8_t { kUtc, kLocal };  // "utc" | "local" (time_zone_minutes_west)
// ACK 0x010310's data (everything after its response code).
enum class GpsAnswerByteOrder : uint8_t { kAck, kBig, kLittle };  // "ack" | "big" | "little"
// ACK 0x010320 with code OK and latitude = longitude = 0.
enum class LaserTargetZeros : uint8_t { kNoReturn, kPosition };  // "no_return" | "position"
// 0x000313 codes 1 ("+") and 2 ("-") of manual focus.
enum class FocusPlus : uint8_t { kNear, kFar };  // "near": code 1 focuses nearer | "far"

// The readings this file adds, with their defaults (docs/protocol/decisions.md#conventions).
struct Conventions {
  YawSign yaw_sign = YawSign::kRight;
  PitchSign pitch_sign = PitchSign::kUp;
  RollSign roll_sign = RollSign::kRightDown;
  AttitudeOrder attitude_order = AttitudeOrder::kZyx;
  YawRange yaw_range = YawRange::kAuto;
  SdCapacityUnit sd_capacity_unit = SdCapacityUnit::k10Mb;
  ShutterField shutter_field = ShutterField::kMicroseconds;
  EnhancementSwitch enhancement_switch = EnhancementSwitch::kBit7;
  ThermalZoomCode thermal_zoom_code = ThermalZoomCode::kRatio;
  CalibrationEnd calibration_end = CalibrationEnd::kAuto;
  PhotoMode2 photo_mode_2 = PhotoMode2::kTimeLapse;
  GpsRequestTime gps_request_time = GpsRequestTime::kUtc;
  GpsAnswerByteOrder gps_answer_byte_order = GpsAnswerByteOrder::kAck;
  LaserTargetZeros laser_target_zeros = LaserTargetZeros::kNoReturn;
  FocusPlus focus_plus = FocusPlus::kNear;
};

// Every reading, wherever it lives: what the table reads and writes.
struct ConventionRefs {
  CrcCoverage& crc_coverage;
  CodecOptions& codec;
  Conventions& conventions;
};

// The same, read-only.
struct ConstConventionRefs {
  const CrcCoverage& crc_coverage;
  const CodecOptions& codec;
  const Conventions& conventions;
};

struct ConventionInfo {
  const char* name;     // ROS parameter = --convention NAME = YAML key
  const char* section;  // of the document, e.g. "3.1.1.2 (0x000002)"
  // The allowed values; empty for a number, whose range `number_range` says.
  std::vector<const char*> values;
  const char* number_range;  // "1..1000" or nullptr
  const char* default_value;
  const char* meaning;  // one line
  // Sets the reading from text; a clear error (naming the reading and its values) otherwise.
  Status (*set)(const ConventionInfo& info, ConventionRefs refs, const std::string& text);
  std::string (*get)(const ConventionInfo& info, ConstConventionRefs refs);
  // true where traffic can tell (the value list has "auto", or the reading is checked against
  // frames and a contradiction shows in the `conventions` diagnostic).
  bool detectable;
};

// Every reading, the ones that existed before this list first.
const std::vector<ConventionInfo>& convention_table();
// nullptr if no reading has that name.
const ConventionInfo* find_convention(const std::string& name);
// "NAME=VALUE" (the simulator's and the tools' option); errors name the reading and its values.
Status set_convention(ConventionRefs refs, const std::string& name, const std::string& value);
Status set_convention_assignment(ConventionRefs refs, const std::string& name_equals_value);
// "a, b or c" for messages and docs.
std::string convention_values_text(const ConventionInfo& info);

}  // namespace k40t::protocol
