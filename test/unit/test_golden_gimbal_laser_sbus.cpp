// Checks of test/data/golden/gimbal_laser_sbus.txt beyond the generic ones of
// test_golden_files.cpp: the file has a frame for every message of its families, each '=' line
// names every field of its message (so the file documents whole messages), and the addresses
// follow the message's direction (section 2.1, docs/protocol/decisions.md#a3).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "golden_checks.h"
#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {
namespace {

using testing::GoldenFrame;

const char kGolden[] = "gimbal_laser_sbus.txt";

// Every frame of the file; each must be one good frame (failing the test otherwise).
std::vector<std::pair<GoldenFrame, testing::SplitFrame>> split_golden() {
  std::vector<std::pair<GoldenFrame, testing::SplitFrame>> frames;
  for (const GoldenFrame& g : testing::load_golden(kGolden))
    frames.emplace_back(g, testing::checked_split(g));
  return frames;
}

bool in_families(MessageId id) {
  const MessageId request = request_id_of(id);
  const bool gimbal_report = request == 0x000001 || request == 0x000002;  // 0x03..0x0F: camera's
  const bool gimbal_request = request >= 0x000010 && request <= 0x0000FF;
  const bool laser_or_sbus = request >= 0x000400 && request <= 0x0005FF;
  return gimbal_report || gimbal_request || laser_or_sbus;
}

bool is_plain_ack(const MessageInfo& m) {
  return m.describe == &describe_payload<PlainAck>;
}

TEST(GimbalLaserSbusGolden, HasAFrameForEveryMessageOfTheFamilies) {
  std::set<MessageId> ids;
  for (const auto& [g, split] : split_golden()) ids.insert(split.header.message_id);
  bool has_plain_ack = false;
  for (const MessageInfo& m : catalogue()) {
    if (!in_families(m.id)) continue;
    if (is_plain_ack(m)) {
      has_plain_ack |= ids.count(m.id) > 0;
      continue;  // one plain ACK stands for all
    }
    EXPECT_EQ(ids.count(m.id), 1u) << "no frame for " << m.name;
  }
  EXPECT_TRUE(has_plain_ack);
  for (MessageId id : ids)
    EXPECT_TRUE(in_families(id)) << display_name(id) << " is another family's";
}

TEST(GimbalLaserSbusGolden, ListsEveryFieldAndUsesTheDirectionsAddresses) {
  const auto frames = split_golden();
  ASSERT_FALSE(frames.empty());
  for (const auto& [g, split] : frames) {
    SCOPED_TRACE(g.where());
    ASSERT_TRUE(split.ok) << split.problem;
    const MessageInfo* info = find_message(split.header.message_id);
    ASSERT_NE(info, nullptr);
    const Address destination = split.header.destination;
    const Address source = split.header.source;
    const Address pod = request_id_of(info->id) <= 0x0000FF ? kGimbalAddress : kCameraAddress;
    if (info->direction == Direction::kHostToPod) {
      EXPECT_EQ(source, kHostAddress);
      EXPECT_EQ(destination, pod);
    } else {
      EXPECT_EQ(source, pod);
      EXPECT_EQ(destination, kHostAddress);
    }

    testing::FieldRecorder decoded;
    ASSERT_TRUE(
        info->describe(split.payload.data(), split.payload.size(), CodecOptions{}, decoded));
    std::set<std::string> decoded_names;
    for (const auto& field : decoded.fields()) decoded_names.insert(field.name);
    std::set<std::string> listed;
    for (const auto& [name, value] : g.expected) listed.insert(name);
    EXPECT_EQ(listed, decoded_names) << info->name << ": the '=' line must list every field";
  }
}

}  // namespace
}  // namespace k40t::protocol
