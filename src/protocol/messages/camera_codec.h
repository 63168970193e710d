// Small wire helpers shared by the camera family's .cpp files (not part of the public API).
#pragma once

#include <cstdint>
#include <initializer_list>

#include "k40t_driver/protocol/message.h"

namespace k40t::protocol::camera_codec {

// check_range for integer fields of any width (the int64_t/double overloads of message.h are
// ambiguous for a uint16_t checked against int literals).
inline Status check_int(const char* field, int64_t value, int64_t lo, int64_t hi,
                        const char* unit = "") {
  return check_range(field, value, lo, hi, unit);
}

// "field 'burst_count' must be one of 3, 5, got 4"
Status check_one_of(const char* field, int64_t value, std::initializer_list<int64_t> allowed,
                    const char* unit = "");

// The photo settings of 0x000301 and 0x000003: time-lapse interval 5/7/30/60 s, burst 3/5 photos.
Status check_photo_settings(uint8_t time_lapse_interval_s, uint8_t burst_count);

}  // namespace k40t::protocol::camera_codec
