// The catalogue holds every message of NOTES.md §1 "Message catalogue", with the ACK of every
// request, and its entries are consistent.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "document_messages.h"
#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {
namespace {

using namespace document;

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
