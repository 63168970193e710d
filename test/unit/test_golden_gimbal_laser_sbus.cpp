// Checks of test/data/golden/gimbal_laser_sbus.txt beyond the generic ones of
// test_golden_files.cpp: the file has a frame for every message of its families, each '=' line
// names every field of its message (so the file documents whole messages), and the addresses
// follow the message's direction (section 2.1, NOTES A3).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "field_recorder.h"
#include "k40t_driver/protocol/catalogue.h"
#include "message_test_util.h"

namespace k40t::protocol {
namespace {

using testing::gimbal_laser_sbus_golden;
using testing::id_of;

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
  for (const auto& g : gimbal_laser_sbus_golden()) ids.insert(id_of(g));
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
  ASSERT_FALSE(gimbal_laser_sbus_golden().empty());
  for (const auto& g : gimbal_laser_sbus_golden()) {
    SCOPED_TRACE(g.where);
    const MessageInfo* info = find_message(id_of(g));
    ASSERT_NE(info, nullptr);
    const Address destination{g.bytes[2], g.bytes[3]};
    const Address source{g.bytes[5], g.bytes[6]};
    const Address pod = request_id_of(info->id) <= 0x0000FF ? kGimbalAddress : kCameraAddress;
    if (info->direction == Direction::kHostToPod) {
      EXPECT_EQ(source, kHostAddress);
      EXPECT_EQ(destination, pod);
    } else {
      EXPECT_EQ(source, pod);
      EXPECT_EQ(destination, kHostAddress);
    }

    testing::FieldRecorder decoded;
    const std::vector<uint8_t> payload = testing::payload_of(g);
    ASSERT_TRUE(info->describe(payload.data(), payload.size(), CodecOptions{}, decoded));
    std::set<std::string> decoded_names;
    for (const auto& [name, value] : decoded.fields()) decoded_names.insert(name);
    std::set<std::string> listed;
    for (const auto& [name, value] : g.expected) listed.insert(name);
    EXPECT_EQ(listed, decoded_names) << info->name << ": the '=' line must list every field";
  }
}

}  // namespace
}  // namespace k40t::protocol
