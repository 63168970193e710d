#include "k40t_driver/psdk/crc.h"

#include <array>

namespace k40t::psdk {
namespace {

// Entry i: i in the top byte of a Width-bit register, shifted out MSB-first eight times. This is
// the "normal" (non-reflected) table; pairing it with a right-shifting update is what DJI's
// sources do, and it is deliberate here (docs/psdk.md#frames).
template <class Uint, Uint kPoly>
constexpr std::array<Uint, 256> make_msb_first_table() {
  constexpr int kWidth = sizeof(Uint) * 8;
  constexpr Uint kTop = static_cast<Uint>(Uint{1} << (kWidth - 1));
  std::array<Uint, 256> table{};
  for (uint32_t i = 0; i < 256; ++i) {
    Uint reg = static_cast<Uint>(static_cast<Uint>(i) << (kWidth - 8));
    for (int bit = 0; bit < 8; ++bit) {
      reg = (reg & kTop) ? static_cast<Uint>(static_cast<Uint>(reg << 1) ^ kPoly)
                         : static_cast<Uint>(reg << 1);
    }
    table[i] = reg;
  }
  return table;
}

constexpr auto kCrc16Table = make_msb_first_table<uint16_t, 0x1021>();
constexpr auto kCrc32Table = make_msb_first_table<uint32_t, 0x04C11DB7>();
static_assert(kCrc16Table[1] == 0x1021 && kCrc16Table[2] == 0x2042,
              "docs/psdk.md#frames CRC16 table");
static_assert(kCrc32Table[1] == 0x04C11DB7, "docs/psdk.md#frames CRC32 table");

}  // namespace

uint16_t crc16_update(uint16_t crc, const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i)
    crc = static_cast<uint16_t>((crc >> 8) ^ kCrc16Table[(crc ^ data[i]) & 0xFF]);
  return crc;
}

uint32_t crc32_update(uint32_t crc, const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i) crc = (crc >> 8) ^ kCrc32Table[(crc ^ data[i]) & 0xFF];
  return crc;
}

uint16_t crc16_table_entry(uint8_t index) {
  return kCrc16Table[index];
}
uint32_t crc32_table_entry(uint8_t index) {
  return kCrc32Table[index];
}

}  // namespace k40t::psdk
