#include "k40t_driver/protocol/crc.h"

#include <array>
#include <utility>

namespace k40t::protocol {
namespace {

constexpr size_t kSlices = 8;
using Table = std::array<uint16_t, 256>;

// kTables[0] is the classic table for the reflected polynomial 0x8408 (x^16 + x^12 + x^5 + 1),
// built from the same definition the document's crc_accumulate implements bit-parallel.
// kTables[k][b] is the effect of byte b followed by k zero bytes. With them crc16_update folds 8
// bytes with 8 independent lookups ("slicing-by-8") instead of a chain of 8 dependent ones: the
// frame parser's throughput is bounded by this function. (Slicing-by-16 measured slower: frames
// are short, so the tail dominates.)
constexpr std::array<Table, kSlices> make_tables() {
  std::array<Table, kSlices> t{};
  for (uint32_t byte = 0; byte < 256; ++byte) {
    uint16_t crc = static_cast<uint16_t>(byte);
    for (int bit = 0; bit < 8; ++bit) {
      crc =
          (crc & 1) ? static_cast<uint16_t>((crc >> 1) ^ 0x8408) : static_cast<uint16_t>(crc >> 1);
    }
    t[0][byte] = crc;
  }
  for (size_t k = 1; k < kSlices; ++k) {
    for (uint32_t byte = 0; byte < 256; ++byte) {
      const uint16_t prev = t[k - 1][byte];
      t[k][byte] = static_cast<uint16_t>((prev >> 8) ^ t[0][prev & 0xFF]);
    }
  }
  return t;
}
constexpr std::array<Table, kSlices> kTables = make_tables();

// Bytes 2..N-1 of a group: each enters through its own table, independently of the register.
template <size_t N, size_t... I>
inline uint16_t fold_tail(const uint8_t* d, std::index_sequence<I...>) {
  return static_cast<uint16_t>((0 ^ ... ^ kTables[N - 3 - I][d[I + 2]]));
}

// Folds N (2..8) bytes into the register: the 16-bit register overlaps the first two bytes, the
// others enter on their own (and are looked up while the register's lookups are in flight).
template <size_t N>
inline uint16_t fold(uint16_t crc, const uint8_t* d) {
  const uint16_t x = static_cast<uint16_t>(crc ^ (d[0] | d[1] << 8));
  return static_cast<uint16_t>(kTables[N - 1][x & 0xFF] ^ kTables[N - 2][x >> 8] ^
                               fold_tail<N>(d, std::make_index_sequence<N - 2>{}));
}

}  // namespace

uint16_t crc16_update(uint16_t crc, const uint8_t* data, size_t size) {
  for (; size >= 8; data += 8, size -= 8) crc = fold<8>(crc, data);
  if (size >= 4) {
    crc = fold<4>(crc, data);
    data += 4;
    size -= 4;
  }
  if (size >= 2) {
    crc = fold<2>(crc, data);
    data += 2;
    size -= 2;
  }
  if (size == 1) crc = static_cast<uint16_t>((crc >> 8) ^ kTables[0][(crc ^ data[0]) & 0xFF]);
  return crc;
}

}  // namespace k40t::protocol
