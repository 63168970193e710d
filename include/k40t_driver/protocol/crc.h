// The K40T checksum (document section 2.1): the X.25 "crc_accumulate" routine with init 0xFFFF and
// no final xor, i.e. CRC-16/MCRF4XX (reflected polynomial 0x8408). "123456789" -> 0x6F91.
#pragma once

#include <cstddef>
#include <cstdint>

namespace k40t::protocol {

constexpr uint16_t kCrcInit = 0xFFFF;

// Table-driven: one lookup per byte.
uint16_t crc16_update(uint16_t crc, const uint8_t* data, size_t size);

inline uint16_t crc16(const uint8_t* data, size_t size) { return crc16_update(kCrcInit, data, size); }

// The document's own bit-twiddling routine, byte at a time. Kept as the reference the table is
// tested against and as the baseline of the parser benchmark.
inline void crc_accumulate_reference(uint8_t data, uint16_t* crc) {
  uint8_t tmp = static_cast<uint8_t>(data ^ static_cast<uint8_t>(*crc & 0xFF));
  tmp = static_cast<uint8_t>(tmp ^ static_cast<uint8_t>(tmp << 4));
  *crc = static_cast<uint16_t>((*crc >> 8) ^ (tmp << 8) ^ (tmp << 3) ^ (tmp >> 4));
}

}  // namespace k40t::protocol
