// The catalogue holds every message of NOTES.md §1 "Message catalogue", with the ACK of every
// request, and its entries are consistent.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {
namespace {

// Transcribed from NOTES.md §1 (periodic reports, status frames, gimbal/thermal/visible/common
// camera/laser/SBUS requests, the two crossing requests).
const MessageId kReports[] = {0x000001, 0x000002, 0x000003, 0x000004, 0x000005, 0x000008};
const MessageId kStatusFrames[] = {0x020302, 0x020303, 0x020304, 0x020307, 0x02030C, 0x02030D, 0x020406};
const MessageId kRequests[] = {
    // gimbal
    0x000010, 0x000012, 0x000013, 0x000017, 0x000018, 0x00002C, 0x00002D, 0x00002E, 0x00002F,
    0x000030, 0x000031, 0x000033,
    // thermal
    0x000100, 0x000105, 0x000106, 0x000108, 0x00010A, 0x00010B, 0x00010C, 0x00010D, 0x00010E,
    0x00010F, 0x000110, 0x000123, 0x000124, 0x000125, 0x000126,
    // visible
    0x000200, 0x000201, 0x000202, 0x000203, 0x000204, 0x000205, 0x000206, 0x000207, 0x000208,
    0x000209, 0x00020A, 0x00020B,
    // common camera
    0x000300, 0x000301, 0x000302, 0x000303, 0x000304, 0x000306, 0x000307, 0x000308, 0x00030A,
    0x00030B, 0x00030C, 0x00030D, 0x00030E, 0x00030F, 0x000311, 0x000312, 0x000313, 0x000314,
    0x000316, 0x000317, 0x000318, 0x000319, 0x000324,
    // laser, SBUS
    0x000400, 0x000406, 0x000500, 0x000501, 0x000502,
    // crossing: the pod asks the flight controller; the flight controller asks the pod
    0x000310, 0x000320};
// ACKs that carry data beyond the response code (NOTES "ACK" column).
const MessageId kDataAcks[] = {0x010018, 0x010100, 0x010200, 0x010310, 0x010312,
                               0x010317, 0x010320, 0x010400, 0x010502};

TEST(Catalogue, HoldsEveryMessageOfTheNotes) {
  for (MessageId id : kReports) EXPECT_TRUE(is_known_id(id)) << std::hex << "report 0x" << id;
  for (MessageId id : kStatusFrames) EXPECT_TRUE(is_known_id(id)) << std::hex << "status 0x" << id;
  for (MessageId id : kRequests) {
    EXPECT_TRUE(is_known_id(id)) << std::hex << "request 0x" << id;
    EXPECT_TRUE(is_known_id(ack_id_of(id))) << std::hex << "ack of 0x" << id;
  }
  for (MessageId id : kDataAcks) {
    const MessageInfo* info = find_message(id);
    ASSERT_NE(info, nullptr) << std::hex << "data ack 0x" << id;
    EXPECT_GT(info->size, 2u) << info->name << " should carry more than the response code";
  }
}

TEST(Catalogue, NamesAreUniqueAndLookupsAgree) {
  std::set<std::string> names;
  for (const MessageInfo& m : catalogue()) {
    EXPECT_TRUE(names.insert(m.name).second) << "duplicate name " << m.name;
    EXPECT_EQ(find_message(m.id), &m);
    EXPECT_EQ(find_message(std::string(m.name)), &m);
    EXPECT_LE(m.min_size, m.size) << m.name;
    EXPECT_LE(m.size, kMaxPayloadSize) << m.name;
    EXPECT_NE(m.describe, nullptr) << m.name;
    EXPECT_NE(std::string(m.section), "") << m.name;
  }
}

TEST(Catalogue, UnknownIdsAreUnknown) {
  EXPECT_FALSE(is_known_id(0x000099));
  EXPECT_FALSE(is_known_id(0x7F0001));
  EXPECT_EQ(find_message(std::string("no_such_message")), nullptr);
}

}  // namespace
}  // namespace k40t::protocol
