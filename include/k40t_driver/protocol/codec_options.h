// The decisions of docs/protocol/decisions.md that change bytes on the wire, as options with
// the defaults recorded there. Every encoder and decoder takes them, so a pod that disagrees with a
// decision is a parameter away.
#pragma once

#include <string>

#include "k40t_driver/protocol/byte_io.h"
#include "k40t_driver/protocol/convention_values.h"
#include "k40t_driver/protocol/message_id.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::protocol {

// docs/protocol/decisions.md#a1: which bytes the checksum covers.
enum class CrcCoverage {
  kHeaderExcluded,  // bytes 1 .. end of payload (MAVLink convention; default)
  kWholeFrame,      // bytes 0 .. end of payload (STX included)
  kAuto,            // parser accepts both and locks onto what the device uses
};

const char* to_string(CrcCoverage coverage);
Result<CrcCoverage> parse_crc_coverage(
    const std::string& text);  // "auto" | "header_excluded" | "whole_frame"
Result<ByteOrder> parse_byte_order(const std::string& text);  // "big" | "little"
const char* to_string(ByteOrder order);

// The largest angle_command_scale at which 0x000012's widest angle (180 deg of yaw) still fits
// the uint16 magnitude: 65535 / 180 = 364.08. A larger one would saturate (at 1000, 90 deg would
// go out as 65.5 deg), so the parameter and the simulator's --angle-scale stop here.
inline constexpr int kMaxAngleCommandScale = 364;

struct CodecOptions {
  // docs/protocol/decisions.md#a2: multi-byte fields of ACK payloads (response code included).
  // Sections that say "low byte first" for their ACK (0x010320) ignore this.
  ByteOrder ack_byte_order = ByteOrder::kBig;
  // `ack_byte_order: auto`: start with ack_byte_order (big) and lock onto the order the pod's
  // first telling ACK shows (protocol/ack_order_setting.h). Never set in the simulator.
  bool ack_byte_order_auto = false;
  // Status frame 0x020406 (periodic laser range). Section 2.1 makes every non-ACK payload low
  // byte first, and 0x020406 is a status frame; its payload merely looks like ACK 0x010400's.
  // Decision (docs/protocol/gimbal_laser_sbus.md): little, a parameter in case a pod builds the
  // frame with its ACK routine.
  ByteOrder laser_status_byte_order = ByteOrder::kLittle;
  // docs/protocol/decisions.md#a4: the 16-bit angle magnitudes of 0x000012 are degrees x
  // angle_command_scale.
  int angle_command_scale = 100;
  // docs/protocol/decisions.md#a3: where requests are addressed.
  Address gimbal_address = kGimbalAddress;
  Address camera_address = kCameraAddress;
  // The document's other open readings (docs/protocol/decisions.md#conventions).
  Conventions conventions;
};

// ack_byte_order's value: "big" | "little" | "auto" (ack_byte_order_auto; order big until locked).
Status parse_ack_byte_order(const std::string& text, CodecOptions& codec);

}  // namespace k40t::protocol
