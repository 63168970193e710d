// The two checksums of a DJI PSDK v1 frame (docs/psdk.md#frames; the protocol document names them
// but does not define them):
//   CRC16 over the header (bytes 0..9): table built MSB-first from 0x1021, but updated with a
//     right shift, crc = (crc >> 8) ^ table[(crc ^ byte) & 0xFF], start 0x3FDE, no final xor.
//     No standard reflect-in/reflect-out parameter set reproduces it, so this is that exact loop.
//     "123456789" -> 0xEBEC.
//   CRC32 over SOF..end of DATA: the same structure with 0x04C11DB7, start 0xFFFFFFFF, final
//     xor 0xFFFFFFFF. "123456789" -> 0x7EAD5C77.
#pragma once

#include <cstddef>
#include <cstdint>

namespace k40t::psdk {

constexpr uint16_t kCrc16Init = 0x3FDE;
constexpr uint32_t kCrc32Init = 0xFFFFFFFF;
constexpr uint32_t kCrc32FinalXor = 0xFFFFFFFF;

// Continue a CRC over more bytes (no final xor applied): for streaming.
uint16_t crc16_update(uint16_t crc, const uint8_t* data, size_t size);
uint32_t crc32_update(uint32_t crc, const uint8_t* data, size_t size);

inline uint16_t crc16(const uint8_t* data, size_t size) {
  return crc16_update(kCrc16Init, data, size);
}
inline uint32_t crc32(const uint8_t* data, size_t size) {
  return crc32_update(kCrc32Init, data, size) ^ kCrc32FinalXor;
}

// Table entry `index` (exposed for the tests that pin table[1] and table[2] to
// docs/psdk.md#frames).
uint16_t crc16_table_entry(uint8_t index);
uint32_t crc32_table_entry(uint8_t index);

}  // namespace k40t::psdk
