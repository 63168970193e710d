// Small pieces shared by the thermal and visible messages (src only: not part of the API). The
// command-byte and switch readers the templates of setting_request.h need are defined in
// setting_bytes.cpp too.
#pragma once

#include <cstdint>

#include "k40t_driver/protocol/byte_io.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/setting_request.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::protocol::detail {

// An unsigned setting against the document's range, e.g. "field 'sharpness' must be 0..100".
inline Status check_level(const char* field, unsigned value, int64_t lo, int64_t hi) {
  return check_range(field, static_cast<int64_t>(value), lo, hi);
}

// A byte holding a switch in bit 7 and a level 0..127 in bits 6..0 (the settings ACKs 0x010100
// and 0x010200 pack denoise, enhancement, backlight and strong light this way).
constexpr uint8_t kSwitchBit = 0x80;
constexpr uint8_t kLevelMask = 0x7F;
inline uint8_t pack_switch_and_level(bool on, uint8_t level) {
  return static_cast<uint8_t>((on ? kSwitchBit : 0) | (level & kLevelMask));
}
inline void unpack_switch_and_level(uint8_t byte, bool* on, uint8_t* level) {
  *on = (byte & kSwitchBit) != 0;
  *level = byte & kLevelMask;
}

// The "read all settings" ACKs carry either the response code alone (a refusal) or the code and
// `settings_size` bytes; `after_code` bytes came after the code. Sets *has_settings, or fails
// naming the byte counts.
Status settings_follow(size_t after_code, ResponseCode code, size_t settings_size,
                       bool* has_settings);

// An enum field as its raw byte.
template <class E>
uint8_t code_of(E value) {
  return static_cast<uint8_t>(value);
}

}  // namespace k40t::protocol::detail
