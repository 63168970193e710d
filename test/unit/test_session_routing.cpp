// Session receive side and sending of non-request frames: typed routing of reports, decode
// errors, requests from the other side (0x000310), sequence numbers, raw/tx.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "session_test_link.h"

namespace k40t::test {
namespace {

using namespace std::chrono_literals;
using protocol::FrameView;
using protocol::Payload;

constexpr protocol::MessageId kGpsRequest = 0x000310;
constexpr protocol::MessageId kGimbalVersion = 0x000018;  // any request the pod ACKs

TEST(SessionRouting, PeriodicReportReachesItsTypedHandler) {
  SessionLink link;
  Collector<std::pair<protocol::GimbalAttitude, protocol::Address>> received;
  link.host->dispatcher().on<protocol::GimbalAttitude>(
      [&](const protocol::GimbalAttitude& a, const FrameView& f) {
        received.add({a, f.header.source});
      });
  link.start();

  protocol::GimbalAttitude sent;
  sent.joint_yaw_deg = 12.34;
  sent.pitch_deg = -45.5;
  sent.roll_rate_deg_s = 3.21;
  ASSERT_TRUE(link.pod->send_message(sent, protocol::kHostAddress));
  ASSERT_TRUE(received.wait_for_count(1));
  const protocol::GimbalAttitude got = received.items()[0].first;
  EXPECT_DOUBLE_EQ(got.joint_yaw_deg, 12.34);
  EXPECT_DOUBLE_EQ(got.pitch_deg, -45.5);
  EXPECT_DOUBLE_EQ(got.roll_rate_deg_s, 3.21);
  EXPECT_EQ(received.items()[0].second, protocol::kCameraAddress);
  EXPECT_EQ(link.host->stats().requests_unhandled, 0u);  // a report is not a request
}

TEST(SessionRouting, InvalidReportIsNotSent) {
  SessionLink link;
  link.start();
  protocol::GimbalAttitude bad;
  bad.yaw_deg = 400;  // int16 x100 holds at most 327.67
  const Status s = link.pod->send_message(bad, protocol::kHostAddress);
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("yaw_deg"), std::string::npos) << s.message();
  EXPECT_TRUE(link.pod_wire->written().empty());
}

TEST(SessionRouting, UndecodablePayloadGoesToTheDecodeErrorHandler) {
  SessionLink link;
  Collector<protocol::GimbalAttitude> attitudes;
  Collector<std::string> errors;
  link.host->dispatcher().on<protocol::GimbalAttitude>(
      [&](const protocol::GimbalAttitude& a, const FrameView&) { attitudes.add(a); });
  link.host->dispatcher().on_decode_error(
      [&](const FrameView&, const std::string& e) { errors.add(e); });
  link.start();

  const uint8_t short_payload[] = {0x01, 0x02, 0x03, 0x04};  // 0x000002 needs 18 bytes at least
  ASSERT_TRUE(link.pod->send_frame(protocol::GimbalAttitude::kId, short_payload, 4,
                                   protocol::kHostAddress));
  ASSERT_TRUE(errors.wait_for_count(1));
  EXPECT_NE(errors.items()[0].find("gimbal_attitude"), std::string::npos) << errors.items()[0];
  EXPECT_NE(errors.items()[0].find("too short"), std::string::npos) << errors.items()[0];
  EXPECT_EQ(attitudes.size(), 0u);
  EXPECT_EQ(link.host->stats().decode_errors, 1u);
  EXPECT_EQ(link.host->stats().parser.frames_good, 1u);
}

// An observer of the ACK (the driver's box-tracking and capture-mode guards) must have seen it
// before the requester wakes, or the caller's next request reads a state the pod left already.
// The observer is slow on purpose (registered after the session's own handler, as the driver's
// are): were the request completed first, it would return while the observer still sleeps.
TEST(SessionRouting, ObserversOfAnAckSeeItBeforeItsRequestReturns) {
  SessionLink link;
  std::atomic<bool> observed{false};
  link.host->dispatcher().on_frame([&](const FrameView& f) {
    if (f.header.message_id != protocol::ack_id_of(kGimbalVersion)) return;
    std::this_thread::sleep_for(100ms);
    observed = true;
  });
  link.pod->set_request_handler(
      kGimbalVersion, [&](const FrameView&) { return std::optional<Payload>(ack_payload(0, {})); });
  link.start();
  const uint8_t request[] = {0x00};
  const session::AckResult r = link.host->request_raw(kGimbalVersion, request, sizeof(request));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(observed.load()) << "the request returned before an observer saw its ACK";
}

TEST(SessionRouting, PodGpsRequestIsAnsweredAsTheFlightController) {
  SessionLink link;
  Collector<protocol::FrameHeader> host_saw;
  link.host->set_request_handler(kGpsRequest, [&](const FrameView& f) {
    host_saw.add(f.header);
    // Section 3.2.4.15: the ACK echoes the time (bytes 3-7) after the response code.
    std::vector<uint8_t> extra(f.payload + 1, f.payload + 6);
    return std::optional<Payload>(ack_payload(0, extra));
  });
  Collector<protocol::FrameHeader> pod_saw;
  link.pod->dispatcher().on_frame([&](const FrameView& f) { pod_saw.add(f.header); });
  link.start();

  // The pod asks for GPS at 12:34:56.789 (section 3.2.4.15): lens enabled, h, m, s, ms LE.
  const uint8_t request[] = {0x01, 12, 34, 56, 0x15, 0x03};
  const session::AckResult r = link.pod->request_raw(kGpsRequest, request, sizeof(request));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.payload, (std::vector<uint8_t>{0x00, 0x00, 12, 34, 56, 0x15, 0x03}));

  ASSERT_TRUE(host_saw.wait_for_count(1));
  EXPECT_EQ(host_saw.items()[0].destination, protocol::kFlightControllerAddress);
  EXPECT_EQ(host_saw.items()[0].source, protocol::kCameraAddress);
  ASSERT_TRUE(pod_saw.wait_for_count(1));
  EXPECT_EQ(pod_saw.items()[0].message_id, 0x010310u);
  EXPECT_EQ(pod_saw.items()[0].source, protocol::kFlightControllerAddress);
  EXPECT_EQ(pod_saw.items()[0].destination, protocol::kCameraAddress);
  EXPECT_EQ(link.host->stats().requests_answered, 1u);
}

TEST(SessionRouting, PodRoleAnswersFromTheAddressTheRequestWentTo) {
  SessionLink link;
  link.pod->set_request_handler(
      0x000018, [](const FrameView&) { return std::optional<Payload>(ack_payload(0)); });
  Collector<protocol::FrameHeader> acks;
  link.host->dispatcher().on_frame([&](const FrameView& f) { acks.add(f.header); });
  link.start();
  const uint8_t version[] = {0x01, 0x00};
  ASSERT_TRUE(link.host->request_raw(0x000018, version, 2).ok());
  ASSERT_TRUE(acks.wait_for_count(1));
  EXPECT_EQ(acks.items()[0].source,
            protocol::kGimbalAddress);  // the gimbal's 0x03 (docs/protocol/decisions.md#a3)
  EXPECT_EQ(acks.items()[0].destination, protocol::kHostAddress);
}

TEST(SessionRouting, SequenceNumbersWrapPerSender) {
  SessionLink link;
  Collector<std::pair<uint8_t, uint8_t>> seen;  // (source system, sequence)
  link.host->dispatcher().on_frame([&](const FrameView& f) {
    seen.add({f.header.source.system, f.header.sequence});
  });
  link.start();
  const uint8_t payload[] = {0x00, 0x00};
  for (int i = 0; i < 258; ++i) {
    ASSERT_TRUE(link.pod->send_frame(0x020304, payload, 2, protocol::kHostAddress));
    // A second sender (the gimbal's address) interleaved: its own counter.
    if (i % 100 == 0) {
      ASSERT_TRUE(link.pod->send_frame_from(protocol::kGimbalAddress, 0x000001, payload, 2,
                                            protocol::kHostAddress));
    }
  }
  ASSERT_TRUE(seen.wait_for_count(261));
  std::vector<uint8_t> camera;
  std::vector<uint8_t> gimbal;
  for (const auto& s : seen.items()) (s.first == 0x04 ? camera : gimbal).push_back(s.second);
  ASSERT_EQ(camera.size(), 258u);
  for (size_t i = 0; i < camera.size(); ++i) EXPECT_EQ(camera[i], static_cast<uint8_t>(i)) << i;
  EXPECT_EQ(gimbal, (std::vector<uint8_t>{0, 1, 2}));
  // The receiver agrees: no gap across the wrap.
  EXPECT_EQ(link.host->stats().parser.sequence_gaps, 0u);
  EXPECT_EQ(link.pod->stats().frames_sent, 261u);
}

TEST(SessionRouting, FrameSentHandlerSeesEveryWrittenFrame) {
  SessionLink link;
  std::vector<std::vector<uint8_t>> sent;  // on_frame_sent runs on the sending thread
  link.pod->on_frame_sent(
      [&](const FrameView& f) { sent.emplace_back(f.bytes, f.bytes + f.size); });
  link.start();
  const uint8_t payload[] = {0x01, 0x02, 0x03};
  ASSERT_TRUE(link.pod->send_frame(0x020302, payload, 3, protocol::kHostAddress));
  ASSERT_TRUE(link.pod->send_frame(0x020302, payload, 3, protocol::kHostAddress));
  ASSERT_EQ(sent.size(), 2u);
  std::vector<uint8_t> joined = sent[0];
  joined.insert(joined.end(), sent[1].begin(), sent[1].end());
  EXPECT_EQ(joined, link.pod_wire->written());
}

TEST(SessionRouting, GarbageBetweenFramesIsCountedAndSkipped) {
  SessionLink link;
  Collector<protocol::LaserRangeAck> acks;
  link.host->dispatcher().on<protocol::LaserRangeAck>(
      [&](const protocol::LaserRangeAck& a, const FrameView&) { acks.add(a); });
  link.start();
  // ACK 0x010400 from the camera, 12.3 m, SEQ 0 (section 3.2.5.1; checksum by frame_crc.py),
  // behind garbage with a false STX. Nothing was outstanding, so it also counts as late.
  link.host_wire->inject({0x55, 0xFD, 0xFF, 0x00, 0xFD, 0x04, 0x01, 0x01, 0x00, 0x04,
                          0x01, 0x00, 0x04, 0x01, 0x00, 0x00, 0x00, 0x7B, 0x82, 0x9E});
  ASSERT_TRUE(acks.wait_for_count(1));
  EXPECT_DOUBLE_EQ(acks.items()[0].distance_m, 12.3);
  for (int i = 0; i < 1000 && link.host->stats().late_acks == 0; ++i)
    std::this_thread::sleep_for(1ms);
  const session::SessionStats s = link.host->stats();
  EXPECT_EQ(s.late_acks, 1u);
  EXPECT_EQ(s.parser.frames_good, 1u);
  EXPECT_EQ(s.parser.bytes_discarded, 4u);
}

}  // namespace
}  // namespace k40t::test
