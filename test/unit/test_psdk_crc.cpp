// PSDK CRC16 and CRC32 (docs/psdk.md#frames): the check values and table entries the document
// gives.
#include <gtest/gtest.h>

#include <cstring>

#include "k40t_driver/psdk/crc.h"

namespace k40t::psdk {
namespace {

const uint8_t kCheckInput[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};

TEST(PsdkCrc, Crc16CheckValue) {
  EXPECT_EQ(crc16(kCheckInput, sizeof(kCheckInput)), 0xEBEC);
}

TEST(PsdkCrc, Crc32CheckValue) {
  EXPECT_EQ(crc32(kCheckInput, sizeof(kCheckInput)), 0x7EAD5C77u);
}

TEST(PsdkCrc, TablesAreBuiltMsbFirst) {
  EXPECT_EQ(crc16_table_entry(0), 0x0000);
  EXPECT_EQ(crc16_table_entry(1), 0x1021);
  EXPECT_EQ(crc16_table_entry(2), 0x2042);
  EXPECT_EQ(crc32_table_entry(1), 0x04C11DB7u);
  EXPECT_EQ(crc32_table_entry(2), 0x09823B6Eu);
}

TEST(PsdkCrc, EmptyInputGivesTheStartValues) {
  EXPECT_EQ(crc16(nullptr, 0), kCrc16Init);
  EXPECT_EQ(crc32(nullptr, 0), kCrc32Init ^ kCrc32FinalXor);
}

TEST(PsdkCrc, UpdatingInPiecesEqualsOnePass) {
  for (size_t split = 0; split <= sizeof(kCheckInput); ++split) {
    const uint16_t c16 = crc16_update(crc16_update(kCrc16Init, kCheckInput, split),
                                      kCheckInput + split, sizeof(kCheckInput) - split);
    EXPECT_EQ(c16, 0xEBEC) << "split at " << split;
    const uint32_t c32 = crc32_update(crc32_update(kCrc32Init, kCheckInput, split),
                                      kCheckInput + split, sizeof(kCheckInput) - split) ^
                         kCrc32FinalXor;
    EXPECT_EQ(c32, 0x7EAD5C77u) << "split at " << split;
  }
}

TEST(PsdkCrc, DiffersFromTheStandardReflectedCrc32) {
  // CRC-32/ISO-HDLC of "123456789" is 0xCBF43926: the PSDK variant must not be it.
  EXPECT_NE(crc32(kCheckInput, sizeof(kCheckInput)), 0xCBF43926u);
}

}  // namespace
}  // namespace k40t::psdk
