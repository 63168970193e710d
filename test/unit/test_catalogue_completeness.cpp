// The catalogue holds exactly the messages of the docs/protocol/*.md message tables (the checked
// transcription of the document's message list, read by docs_message_tables.h), with the ACK of
// every request, and its entries are consistent.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <type_traits>

#include "docs_message_tables.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/all.h"

namespace k40t::protocol {
namespace {

const testing::DocsMessages& docs() {
  static const testing::DocsMessages loaded = testing::load_docs_messages();
  return loaded;
}

TEST(Catalogue, DocsMessageTablesParseAndNameEachIdOnce) {
  for (const std::string& problem : docs().problems) ADD_FAILURE() << problem;
  std::set<MessageId> ids;
  for (const testing::DocsMessage& m : docs().rows) {
    EXPECT_TRUE(ids.insert(m.id).second) << m.where << ": 0x" << std::hex << m.id << " twice";
  }
  // Gimbal, thermal, visible, camera, laser and SBUS tables are all read.
  for (MessageId id : {0x000002u, 0x000004u, 0x000005u, 0x000003u, 0x000400u, 0x000500u}) {
    EXPECT_EQ(ids.count(id), 1u) << std::hex << "0x" << id << " is in no docs table";
  }
}

TEST(Catalogue, HoldsEveryMessageOfTheDocsTables) {
  for (const testing::DocsMessage& m : docs().rows) {
    SCOPED_TRACE(m.where);
    const MessageInfo* info = find_message(m.id);
    ASSERT_NE(info, nullptr) << std::hex << "0x" << m.id << " is not in the catalogue";
    EXPECT_EQ(info->name, m.name);
    EXPECT_EQ(info->section, m.section);
    EXPECT_EQ(info->size, m.size);
    EXPECT_EQ(info->min_size, m.min_size);
    EXPECT_NE(info->describe, &describe_payload<PlainAck>) << "listed, so not a bare-code ACK";
    switch (kind_of(m.id)) {
      case MessageKind::kRequestOrReport:
        if (!is_periodic_report(m.id)) {
          EXPECT_TRUE(is_known_id(ack_id_of(m.id))) << "no ACK of request " << m.name;
        }
        break;
      case MessageKind::kAck:  // a listed ACK carries data
        EXPECT_GT(info->size, PlainAck::kSize) << m.name;
        EXPECT_NE(find_message(request_id_of(m.id)), nullptr) << m.name << " acknowledges nothing";
        break;
      default:
        break;
    }
  }
}

TEST(Catalogue, HoldsNothingTheDocsTablesLack) {
  std::set<MessageId> listed;
  for (const testing::DocsMessage& m : docs().rows) listed.insert(m.id);
  for (const MessageInfo& info : catalogue()) {
    const bool generated_ack = info.describe == &describe_payload<PlainAck>;
    if (generated_ack) {
      EXPECT_EQ(listed.count(request_id_of(info.id)), 1u) << info.name << " of an unlisted request";
    } else {
      EXPECT_EQ(listed.count(info.id), 1u) << info.name << " has no row in docs/protocol/";
    }
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

// The catalogue is the families' type lists (messages/all.h) plus a generated "<request>_ack"
// entry for each request whose ACK has no struct: a struct missing from its family's list, or
// listed twice, fails here.
TEST(Catalogue, IsTheFamiliesTypeListsPlusTheGeneratedPlainAcks) {
  std::multiset<MessageId> listed;
  for_each_message(PodMessages{}, [&](auto* type) {
    using T = std::remove_pointer_t<decltype(type)>;
    listed.insert(T::kId);
    const MessageInfo* info = find_message(T::kId);
    ASSERT_NE(info, nullptr) << T::kName;
    EXPECT_STREQ(info->name, T::kName);
    EXPECT_EQ(info->describe, &describe_payload<T>) << T::kName;
  });
  for (const MessageInfo& m : catalogue()) {
    if (m.describe == &describe_payload<PlainAck>) {
      EXPECT_EQ(listed.count(m.id), 0u) << m.name;
      const MessageInfo* request = find_message(request_id_of(m.id));
      ASSERT_NE(request, nullptr) << m.name;
      EXPECT_EQ(std::string(m.name), std::string(request->name) + "_ack");
    } else {
      EXPECT_EQ(listed.count(m.id), 1u) << m.name << " is listed once in its family's list";
    }
  }
  EXPECT_EQ(listed.size(), PodMessages::kSize);
}

TEST(Catalogue, UnknownIdsAreUnknown) {
  EXPECT_FALSE(is_known_id(0x000099));
  EXPECT_FALSE(is_known_id(0x7F0001));
  EXPECT_EQ(find_message(std::string("no_such_message")), nullptr);
}

}  // namespace
}  // namespace k40t::protocol
