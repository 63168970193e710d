// The values of the document's open readings (docs/protocol/decisions.md#conventions), one enum
// per reading, and their defaults. CodecOptions carries them, so every encoder, decoder and
// conversion that sees the codec options sees them; protocol/conventions.h names and parses them.
#pragma once

#include <cstdint>

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

}  // namespace k40t::protocol
