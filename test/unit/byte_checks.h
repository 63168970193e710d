// THE comparison of byte strings in the unit tests' golden checks: hex as the golden files
// write it, and the offset of the first difference.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace k40t::testing {

// Bytes as the golden files write them ("FD 02 04"), so a mismatch reads like the file.
inline std::string hex_bytes(const std::vector<uint8_t>& bytes) {
  static const char kDigits[] = "0123456789ABCDEF";
  std::string out;
  for (uint8_t b : bytes) {
    if (!out.empty()) out += ' ';
    out += kDigits[b >> 4];
    out += kDigits[b & 0x0F];
  }
  return out;
}

// THE byte comparison: equal, or a failure with both sides in hex and the first differing byte.
inline ::testing::AssertionResult same_bytes(const std::vector<uint8_t>& actual,
                                             const std::vector<uint8_t>& expected) {
  if (actual == expected) return ::testing::AssertionSuccess();
  size_t at = 0;
  while (at < actual.size() && at < expected.size() && actual[at] == expected[at]) ++at;
  return ::testing::AssertionFailure()
         << "bytes differ from byte " << at << " on (of " << expected.size() << " expected, "
         << actual.size() << " got)\n  expected: " << hex_bytes(expected)
         << "\n  got:      " << hex_bytes(actual);
}

}  // namespace k40t::testing
