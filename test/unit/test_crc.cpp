// CRC-16/MCRF4XX as the document defines it (section 2.1, crc_accumulate with X25_INIT_CRC).
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "k40t_driver/protocol/crc.h"

namespace k40t::protocol {
namespace {

TEST(Crc, CheckValueOfTheCatalogue) {
  // The standard check input of CRC-16/MCRF4XX; docs/protocol/decisions.md#checksum quotes 0x6F91.
  const std::string check = "123456789";
  EXPECT_EQ(crc16(reinterpret_cast<const uint8_t*>(check.data()), check.size()), 0x6F91);
}

TEST(Crc, EmptyInputIsTheInitValue) {
  EXPECT_EQ(crc16(nullptr, 0), 0xFFFF);
}

TEST(Crc, TableMatchesTheDocumentsRoutineOnRandomData) {
  std::mt19937 rng(7);
  for (int round = 0; round < 200; ++round) {
    std::vector<uint8_t> data(rng() % 300);
    for (auto& b : data) b = static_cast<uint8_t>(rng());
    uint16_t reference = kCrcInit;
    for (uint8_t b : data) crc_accumulate_reference(b, &reference);
    ASSERT_EQ(crc16(data.data(), data.size()), reference) << "size " << data.size();
  }
}

TEST(Crc, UpdateIsIncremental) {
  const uint8_t data[] = {0xFD, 0x02, 0x04, 0x01, 0x00, 0x01, 0x01, 0x00, 0x04, 0x00};
  const uint16_t whole = crc16(data, sizeof data);
  const uint16_t split = crc16_update(crc16(data, 4), data + 4, sizeof data - 4);
  EXPECT_EQ(whole, split);
}

}  // namespace
}  // namespace k40t::protocol
