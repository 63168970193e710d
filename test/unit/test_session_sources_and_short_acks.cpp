// Issue 10 fixes in the session: who sends 0x000320 (section 3.2.4.24) and what a local ACK
// decode error reports (never the pod's own response code 0x0007).
#include <gtest/gtest.h>

#include <vector>

#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "session_test_link.h"

namespace k40t::test {
namespace {

using protocol::FrameView;
using protocol::Payload;

std::vector<uint8_t> bytes_of(const FrameView& f) {
  return std::vector<uint8_t>(f.bytes, f.bytes + f.size);
}

TEST(SessionSources, LaserTargetRequestComesFromTheFlightController) {
  SessionLink link;
  Collector<std::vector<uint8_t>> received;
  link.pod->dispatcher().on_frame([&](const FrameView& f) { received.add(bytes_of(f)); });
  link.pod->set_request_handler(
      0x000320, [](const FrameView&) { return std::optional<Payload>(ack_payload(0x0000)); });
  link.pod->set_request_handler(0x000400, [](const FrameView&) {
    return std::optional<Payload>(ack_payload(0x0000, {0x00, 0x7B}));
  });
  link.start();
  EXPECT_TRUE(link.host->request(protocol::TargetGpsRequest{}).received);
  EXPECT_TRUE(link.host->request(protocol::LaserRangeRequest{}).received);
  ASSERT_TRUE(received.wait_for_count(2));
  // Section 2.1: bytes 5 and 6 are the sender's system and component. Section 3.2.4.24: the
  // flight controller (0x02/0x01) sends 0x000320 (id bytes 20 03 00) to the camera (04 01).
  const std::vector<std::vector<uint8_t>> frames = received.items();
  const std::vector<uint8_t>& target = frames[0];
  ASSERT_GE(target.size(), 10u);
  EXPECT_EQ((std::vector<uint8_t>(target.begin() + 2, target.begin() + 4)),
            (std::vector<uint8_t>{0x04, 0x01}));
  EXPECT_EQ((std::vector<uint8_t>(target.begin() + 5, target.begin() + 10)),
            (std::vector<uint8_t>{0x02, 0x01, 0x20, 0x03, 0x00}));
  // Every other request stays the host's (0x01/0x01): 0x000400 = 00 04 00.
  const std::vector<uint8_t>& laser = frames[1];
  EXPECT_EQ((std::vector<uint8_t>(laser.begin() + 5, laser.begin() + 10)),
            (std::vector<uint8_t>{0x01, 0x01, 0x00, 0x04, 0x00}));
}

TEST(SessionShortAcks, AnAckWithoutAResponseCodeIsTheDriversErrorNotThePods) {
  SessionLink link;
  link.pod->set_request_handler(0x000400, [](const FrameView&) {
    Payload one_byte;
    one_byte.bytes[0] = 0x00;
    one_byte.size = 1;
    return std::optional<Payload>(one_byte);
  });
  link.start();
  const session::AckResult r = link.host->request(protocol::LaserRangeRequest{});
  EXPECT_TRUE(r.received);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.code, protocol::ResponseCode::kLengthMismatch);  // 0x0007 is the pod's code
  EXPECT_EQ(r.code, protocol::ResponseCode::kAckUnreadable);
  EXPECT_NE(r.message.find("too few for a response code"), std::string::npos) << r.message;
}

TEST(SessionShortAcks, ResponseCodeReaderMarksAShortPayloadAsUnreadable) {
  const uint8_t one[1] = {0x00};
  EXPECT_EQ(protocol::ack_response_code(one, 1, {}), protocol::ResponseCode::kAckUnreadable);
  const uint8_t pods_length_mismatch[2] = {
      0x00, 0x07};  // section 3.3, big-endian (docs/protocol/decisions.md#a2)
  EXPECT_EQ(protocol::ack_response_code(pods_length_mismatch, 2, {}),
            protocol::ResponseCode::kLengthMismatch);
  EXPECT_EQ(protocol::response_text(protocol::ResponseCode::kAckUnreadable).find("length mismatch"),
            std::string::npos);
}

}  // namespace
}  // namespace k40t::test
