// The thermal and visible families as a whole: every hand-written golden frame decodes through
// the catalogue to its "=" line, every message id of the two families has a golden frame, every
// struct survives a round trip, and the catalogue entries are consistent.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "docs_message_tables.h"
#include "golden_checks.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "message_checks.h"

namespace k40t::protocol {
namespace {

const char kGolden[] = "thermal_visible.txt";

bool in_families(MessageId id) {
  const MessageId request = request_id_of(id);
  return request == 0x000004 || request == 0x000005 || (request >= 0x000100 && request <= 0x0002FF);
}

TEST(ThermalVisibleGoldenFile, EveryFrameDecodesToItsExpectedLine) {
  const std::vector<testing::GoldenFrame> golden = testing::load_golden(kGolden);
  ASSERT_GE(golden.size(), 30u);
  for (const testing::GoldenFrame& frame : golden) {
    SCOPED_TRACE(frame.where() + " " + frame.name);
    const testing::SplitFrame split = testing::split_frame(frame);
    ASSERT_TRUE(split.ok) << split.problem;
    const MessageInfo* info = find_message(split.header.message_id);
    ASSERT_NE(info, nullptr) << "id not in the catalogue";
    EXPECT_TRUE(in_families(info->id));
    EXPECT_EQ(frame.name, info->name) << "the comment names another message";
    EXPECT_EQ(frame.section, info->section) << "the comment cites another section";
    testing::expect_describes_to_expected(frame);
  }
}

TEST(ThermalVisibleGoldenFile, CoversEveryMessageIdOfBothFamilies) {
  std::set<MessageId> covered;
  for (const testing::GoldenFrame& frame : testing::load_golden(kGolden)) {
    covered.insert(testing::split_frame(frame).header.message_id);
  }
  size_t plain_acks = 0;
  std::set<MessageId> family_ids;
  for (const MessageInfo& info : catalogue()) {
    if (!in_families(info.id)) continue;
    family_ids.insert(info.id);
    const bool plain_ack = kind_of(info.id) == MessageKind::kAck && info.size == PlainAck::kSize;
    if (plain_ack) {
      plain_acks += covered.count(info.id);
      continue;
    }
    EXPECT_EQ(covered.count(info.id), 1u) << info.name << " has no golden frame";
  }
  EXPECT_GE(plain_acks, 1u);
  // The docs tables' reports, requests and data ACKs of both families, with the requests' ACKs.
  std::set<MessageId> document_ids;
  const testing::DocsMessages docs = testing::load_docs_messages();
  for (const testing::DocsMessage& m : docs.rows) {
    if (in_families(m.id)) document_ids.insert(m.id);
  }
  for (MessageId id : testing::docs_request_ids(docs)) {
    if (in_families(id)) document_ids.insert(ack_id_of(id));
  }
  EXPECT_EQ(family_ids, document_ids);
}

// The structs of both families, from the lists their headers end with.
using FamilyTypes = JoinedMessages<ThermalMessages, VisibleMessages>;

template <class T>
void round_trip_golden_and_check_entry() {
  testing::expect_round_trip(testing::golden_message<T>(kGolden));
  const MessageInfo* info = find_message(T::kId);
  ASSERT_NE(info, nullptr) << T::kName;
  EXPECT_STREQ(info->name, T::kName);
  EXPECT_EQ(info->size, T::kSize) << T::kName;
  EXPECT_LE(T::kMinSize, T::kSize) << T::kName;
  EXPECT_EQ(find_message(T::kName), info) << T::kName;
}

TEST(ThermalVisibleStructs, EveryStructRoundTripsAndIsInTheCatalogue) {
  for_each_message(FamilyTypes{}, [](auto* type) {
    round_trip_golden_and_check_entry<std::remove_pointer_t<decltype(type)>>();
  });
}

template <class T>
void expect_ack_of_request() {
  const MessageInfo* ack = find_message(ack_id_of(T::kId));
  ASSERT_NE(ack, nullptr) << T::kName;
  EXPECT_EQ(ack->direction, Direction::kPodToHost);
  if constexpr (std::is_same_v<typename T::Ack, PlainAck>) {
    EXPECT_EQ(std::string(ack->name), std::string(T::kName) + "_ack");
    EXPECT_EQ(ack->size, PlainAck::kSize);
  } else {
    EXPECT_EQ(ack->id, T::Ack::kId);
    EXPECT_STREQ(ack->name, T::Ack::kName);
  }
}

TEST(ThermalVisibleStructs, EveryRequestHasItsAckInTheCatalogue) {
  for_each_message(FamilyTypes{}, [](auto* type) {
    using T = std::remove_pointer_t<decltype(type)>;
    if constexpr (T::kDirection == Direction::kHostToPod) expect_ack_of_request<T>();
  });
}

TEST(ThermalVisibleStructs, ValuesBetweenWireStepsRoundToTheNearestStep) {
  ThermalThresholdAlarmRequest threshold;
  threshold.threshold_reference_degC = 12.34;  // -> 123
  threshold.threshold_float_degC = 0.06;       // -> 1
  auto payload = encode_payload(threshold);
  ASSERT_TRUE(payload);
  EXPECT_EQ(payload->bytes[1], 123);
  EXPECT_EQ(payload->bytes[3], 1);
  VisibleStatus status;
  status.focal_length_mm = 4.567;  // -> 457
  payload = encode_payload(status);
  ASSERT_TRUE(payload);
  EXPECT_EQ(payload->bytes[1] | payload->bytes[2] << 8, 457);
}

}  // namespace
}  // namespace k40t::protocol
