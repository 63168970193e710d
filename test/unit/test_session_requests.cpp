// Session request/ACK behaviour (docs/protocol/decisions.md#a3, A5) over an in-memory link: the
// host session against a pod-role session whose handlers play the pod.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "k40t_driver/protocol/messages/laser.h"
#include "session_test_link.h"

namespace k40t::test {
namespace {

using namespace std::chrono_literals;
using protocol::FrameView;
using protocol::Payload;

constexpr protocol::MessageId kLaserRange = 0x000400;
constexpr protocol::MessageId kGimbalVersion = 0x000018;

// A request whose validation can fail, defined here so the test does not depend on the message
// families being written in parallel (zoom ratio 0x000304 of section 3.2.4.5: 1..160 x).
struct TestZoomRequest {
  static constexpr protocol::MessageId kId = 0x000304;
  static constexpr const char* kName = "test_zoom";
  static constexpr const char* kSection = "3.2.4.5";
  static constexpr protocol::Direction kDirection = protocol::Direction::kHostToPod;
  static constexpr size_t kSize = 3;
  static constexpr size_t kMinSize = 3;
  using Ack = protocol::PlainAck;
  double zoom_x = 1;
  Status validate() const { return protocol::check_range("zoom_x", zoom_x, 1.0, 160.0, "x"); }
  void encode(protocol::ByteWriter& w, const protocol::CodecOptions&) const {
    w.u16(protocol::to_wire<uint16_t>(zoom_x, 10));
    w.zeros(1);
  }
  Status decode(protocol::ByteReader& r, const protocol::CodecOptions&) {
    zoom_x = r.u16() / 10.0;
    return Status::ok();
  }
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("zoom_x", self.zoom_x);
  }
};

std::vector<uint8_t> bytes_of(const FrameView& f) {
  return std::vector<uint8_t>(f.bytes, f.bytes + f.size);
}

TEST(SessionRequests, LaserRangeAckIsMatchedAndDecoded) {
  SessionLink link;
  link.pod->set_request_handler(kLaserRange, [](const FrameView&) {
    return std::optional<Payload>(ack_payload(0x0000, {0x00, 0x7B}));  // 12.3 m, section 3.2.5.1
  });
  link.start();

  session::AckResult raw;
  Result<protocol::LaserRangeAck> ack =
      link.host->request_typed(protocol::LaserRangeRequest{}, &raw);
  ASSERT_TRUE(ack) << ack.error();
  EXPECT_DOUBLE_EQ(ack->distance_m, 12.3);
  EXPECT_TRUE(raw.ok());
  EXPECT_EQ(raw.attempts, 1);
  EXPECT_EQ(raw.message, "OK, success");
  EXPECT_EQ(raw.payload, (std::vector<uint8_t>{0x00, 0x00, 0x00, 0x7B}));
  const session::SessionStats s = link.host->stats();
  EXPECT_EQ(s.requests, 1u);
  EXPECT_EQ(s.acks, 1u);
  EXPECT_EQ(s.nacks, 0u);
  EXPECT_EQ(s.frames_sent, 1u);
  EXPECT_EQ(link.pod->stats().requests_answered, 1u);
}

TEST(SessionRequests, RequestBytesFollowTheDocument) {
  SessionLink link;
  Collector<std::vector<uint8_t>> received;
  link.pod->dispatcher().on_frame([&](const FrameView& f) { received.add(bytes_of(f)); });
  link.pod->set_request_handler(
      kLaserRange, [](const FrameView&) { return std::optional<Payload>(ack_payload(0)); });
  link.pod->set_request_handler(
      kGimbalVersion, [](const FrameView&) { return std::optional<Payload>(ack_payload(0)); });
  link.start();

  const uint8_t laser[] = {0x01, 0x00};
  EXPECT_TRUE(link.host->request_raw(kLaserRange, laser, sizeof(laser)).ok());
  const uint8_t version[] = {0x01, 0x00};
  EXPECT_TRUE(link.host->request_raw(kGimbalVersion, version, sizeof(version)).ok());
  ASSERT_TRUE(received.wait_for_count(2));
  // Section 3.2.5.1: host 0x01/0x01 -> camera 0x04/0x01, SEQ 0, id 0x000400 low byte first,
  // payload {01 single ranging, 00 reserved}; checksum by test/data/frame_crc.py (header_excluded).
  EXPECT_EQ(received.items()[0], (std::vector<uint8_t>{0xFD, 0x02, 0x04, 0x01, 0x00, 0x01, 0x01,
                                                       0x00, 0x04, 0x00, 0x01, 0x00, 0xA2, 0x56}));
  // Section 3.1.2.5 with docs/protocol/decisions.md#a3: gimbal ids go to system 0x03; SEQ 1 (the
  // host's second frame); payload {01 get version, 00 reserved}; checksum by frame_crc.py.
  EXPECT_EQ(received.items()[1], (std::vector<uint8_t>{0xFD, 0x02, 0x03, 0x01, 0x01, 0x01, 0x01,
                                                       0x18, 0x00, 0x00, 0x01, 0x00, 0x64, 0x8F}));
}

TEST(SessionRequests, TimeoutRetriesAndCountsAttempts) {
  SessionLink link(host_options(20ms, 2));
  Collector<uint8_t> sequences;
  link.pod->dispatcher().on_frame([&](const FrameView& f) { sequences.add(f.header.sequence); });
  link.start();  // the pod has no handler for 0x000400: it never answers

  const uint8_t payload[] = {0x01, 0x00};
  const session::AckResult r = link.host->request_raw(kLaserRange, payload, sizeof(payload));
  EXPECT_TRUE(r.sent);
  EXPECT_FALSE(r.received);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.attempts, 3);
  EXPECT_EQ(r.code, protocol::ResponseCode::kTimeout);
  EXPECT_NE(r.message.find("laser_range (0x000400)"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("after 3 attempts"), std::string::npos) << r.message;

  const session::SessionStats s = link.host->stats();
  EXPECT_EQ(s.requests, 1u);
  EXPECT_EQ(s.retries, 2u);
  EXPECT_EQ(s.ack_timeouts, 1u);
  EXPECT_EQ(s.acks, 0u);
  EXPECT_EQ(s.frames_sent, 3u);
  // Each attempt is a new frame with the next sequence number.
  ASSERT_TRUE(sequences.wait_for_count(3));
  EXPECT_EQ(sequences.items(), (std::vector<uint8_t>{0, 1, 2}));
  EXPECT_EQ(link.pod->stats().requests_unhandled, 3u);
}

TEST(SessionRequests, ARetryThatIsAnsweredSucceeds) {
  SessionLink link(host_options(50ms, 3));
  std::atomic<int> calls{0};
  link.pod->set_request_handler(kLaserRange, [&](const FrameView&) -> std::optional<Payload> {
    if (calls.fetch_add(1) == 0) return std::nullopt;  // the first ACK is lost
    return ack_payload(0);
  });
  link.start();
  const uint8_t payload[] = {0x01, 0x00};
  const session::AckResult r = link.host->request_raw(kLaserRange, payload, sizeof(payload));
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.attempts, 2);
  EXPECT_EQ(link.host->stats().retries, 1u);
  EXPECT_EQ(link.host->stats().ack_timeouts, 0u);
}

TEST(SessionRequests, NackCarriesTheResponseText) {
  SessionLink link;
  link.pod->set_request_handler(kLaserRange, [](const FrameView&) {
    return std::optional<Payload>(ack_payload(0x0008));  // section 3.3: busy (repeated request)
  });
  link.start();
  const session::AckResult r = link.host->request(protocol::LaserRangeRequest{});
  EXPECT_TRUE(r.sent);
  EXPECT_TRUE(r.received);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.code, protocol::ResponseCode::kBusy);
  EXPECT_NE(r.message.find("busy (repeated request)"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("0x0008"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("laser_range"), std::string::npos) << r.message;
  EXPECT_EQ(link.host->stats().nacks, 1u);
  EXPECT_EQ(link.host->stats().acks, 1u);

  Result<protocol::LaserRangeAck> typed = link.host->request_typed(protocol::LaserRangeRequest{});
  ASSERT_FALSE(typed);
  EXPECT_NE(typed.error().find("busy"), std::string::npos) << typed.error();
}

TEST(SessionRequests, UnlistedResponseCodeIsNamed) {
  SessionLink link;
  link.pod->set_request_handler(
      kLaserRange, [](const FrameView&) { return std::optional<Payload>(ack_payload(0x0777)); });
  link.start();
  const session::AckResult r = link.host->request(protocol::LaserRangeRequest{});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("unknown response code 0x0777"), std::string::npos) << r.message;
}

TEST(SessionRequests, DuplicateAckIsCountedLateAndIgnored) {
  SessionLink link;
  link.pod->set_request_handler(kLaserRange, [&](const FrameView& f) {
    // Answer twice: the second ACK finds no outstanding request.
    const Payload second = ack_payload(0x0001);
    EXPECT_TRUE(link.pod->send_ack(f.header, second.data(), second.size));
    return std::optional<Payload>(ack_payload(0));
  });
  Collector<protocol::MessageId> host_frames;
  link.host->dispatcher().on_frame(
      [&](const FrameView& f) { host_frames.add(f.header.message_id); });
  link.start();

  const session::AckResult r = link.host->request(protocol::LaserRangeRequest{});
  // The first ACK on the wire (the refusal, sent from inside the handler) is the one matched.
  EXPECT_TRUE(r.received);
  EXPECT_EQ(r.code, protocol::ResponseCode::kFailure);
  ASSERT_TRUE(host_frames.wait_for_count(2));
  // The host's frame handlers run before ACK matching, so wait for the counter itself.
  for (int i = 0; i < 1000 && link.host->stats().late_acks == 0; ++i)
    std::this_thread::sleep_for(1ms);
  EXPECT_EQ(link.host->stats().late_acks, 1u);
  EXPECT_EQ(link.host->stats().acks, 1u);
}

TEST(SessionRequests, AckAfterTimeoutIsLate) {
  SessionLink link(host_options(10ms, 0));
  Collector<protocol::FrameHeader> requests;
  link.pod->set_request_handler(kLaserRange, [&](const FrameView& f) -> std::optional<Payload> {
    requests.add(f.header);
    return std::nullopt;  // answered below, after the host gave up
  });
  link.start();
  const session::AckResult r = link.host->request(protocol::LaserRangeRequest{});
  EXPECT_FALSE(r.received);
  ASSERT_TRUE(requests.wait_for_count(1));
  const Payload ack = ack_payload(0);
  ASSERT_TRUE(link.pod->send_ack(requests.items()[0], ack.data(), ack.size));
  for (int i = 0; i < 5000 && link.host->stats().late_acks == 0; ++i)
    std::this_thread::sleep_for(1ms);
  EXPECT_EQ(link.host->stats().late_acks, 1u);
  EXPECT_EQ(link.host->stats().acks, 0u);
  EXPECT_EQ(link.host->stats().ack_timeouts, 1u);
}

TEST(SessionRequests, SecondRequestForAnIdWaitsWhileAnotherIdProceeds) {
  SessionLink link(host_options(10000ms, 0));
  Collector<protocol::FrameHeader> pod_requests;
  const auto record = [&](const FrameView& f) -> std::optional<Payload> {
    pod_requests.add(f.header);
    return std::nullopt;  // the test answers by hand, in its own order
  };
  link.pod->set_request_handler(kLaserRange, record);
  link.pod->set_request_handler(kGimbalVersion, record);
  link.start();

  Collector<std::string> done;
  const uint8_t payload[] = {0x01, 0x00};
  std::thread first([&] {
    const session::AckResult r = link.host->request_raw(kLaserRange, payload, 2);
    done.add(std::string("laser1:") + (r.ok() ? "ok" : r.message));
  });
  ASSERT_TRUE(pod_requests.wait_for_count(1));
  std::thread second([&] {
    const session::AckResult r = link.host->request_raw(kLaserRange, payload, 2);
    done.add(std::string("laser2:") + (r.ok() ? "ok" : r.message));
  });
  std::thread other([&] {
    const session::AckResult r = link.host->request_raw(kGimbalVersion, payload, 2);
    done.add(std::string("version:") + (r.ok() ? "ok" : r.message));
  });
  // The other id reaches the pod while the first laser request is still outstanding; the second
  // laser request does not.
  ASSERT_TRUE(pod_requests.wait_for_count(2));
  EXPECT_EQ(pod_requests.items()[1].message_id, kGimbalVersion);
  const Payload ok = ack_payload(0);
  ASSERT_TRUE(link.pod->send_ack(pod_requests.items()[1], ok.data(), ok.size));
  other.join();
  ASSERT_EQ(done.items(), std::vector<std::string>{"version:ok"});
  EXPECT_EQ(pod_requests.size(), 2u);  // laser 2 still waits behind laser 1

  ASSERT_TRUE(link.pod->send_ack(pod_requests.items()[0], ok.data(), ok.size));
  first.join();
  ASSERT_TRUE(pod_requests.wait_for_count(3));  // now laser 2 goes out
  EXPECT_EQ(pod_requests.items()[2].message_id, kLaserRange);
  ASSERT_TRUE(link.pod->send_ack(pod_requests.items()[2], ok.data(), ok.size));
  second.join();
  EXPECT_EQ(done.items(), (std::vector<std::string>{"version:ok", "laser1:ok", "laser2:ok"}));
  EXPECT_EQ(link.host->stats().late_acks, 0u);
}

TEST(SessionRequests, ValidationFailureWritesNothing) {
  SessionLink link;
  link.start();
  TestZoomRequest zoom;
  zoom.zoom_x = 200;
  const session::AckResult r = link.host->request(zoom);
  EXPECT_FALSE(r.sent);
  EXPECT_FALSE(r.received);
  EXPECT_EQ(r.attempts, 0);
  EXPECT_NE(r.message.find("zoom_x"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("1..160"), std::string::npos) << r.message;

  Result<protocol::PlainAck> typed = link.host->request_typed(zoom);
  EXPECT_FALSE(typed);
  EXPECT_NE(typed.error().find("zoom_x"), std::string::npos);

  std::vector<uint8_t> too_big(244, 0);
  const session::AckResult big =
      link.host->request_raw(kLaserRange, too_big.data(), too_big.size());
  EXPECT_FALSE(big.sent);
  EXPECT_NE(big.message.find("243"), std::string::npos) << big.message;

  const uint8_t payload[] = {0x00, 0x00};
  const session::AckResult not_request = link.host->request_raw(0x010400, payload, 2);
  EXPECT_FALSE(not_request.sent);
  EXPECT_NE(not_request.message.find("not a request"), std::string::npos) << not_request.message;

  EXPECT_TRUE(link.host_wire->written().empty());
  EXPECT_EQ(link.host->stats().frames_sent, 0u);
  EXPECT_EQ(link.host->stats().requests, 0u);
}

TEST(SessionRequests, SendFailureIsReportedWithTheTransportsMessage) {
  SessionLink link;
  link.start();
  link.host_wire->fail_sends(true);
  const session::AckResult r = link.host->request(protocol::LaserRangeRequest{});
  EXPECT_FALSE(r.sent);
  EXPECT_FALSE(r.received);
  EXPECT_NE(r.message.find("could not send laser_range"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("fake://host"), std::string::npos) << r.message;
  EXPECT_EQ(link.host->stats().send_errors, 1u);
  EXPECT_EQ(link.host->stats().requests, 0u);
}

TEST(SessionRequests, RequestBeforeStartIsRejected) {
  SessionLink link;
  const session::AckResult r = link.host->request(protocol::LaserRangeRequest{});
  EXPECT_FALSE(r.sent);
  EXPECT_NE(r.message.find("not running"), std::string::npos) << r.message;
  EXPECT_TRUE(link.host_wire->written().empty());
}

TEST(SessionRequests, StopCompletesOutstandingRequests) {
  SessionLink link(host_options(60000ms, 0));
  link.start();
  Collector<session::AckResult> results;
  const Payload payload = ack_payload(0x0100);  // any two bytes
  link.host->request_async(kLaserRange, payload,
                           [&](const session::AckResult& r) { results.add(r); });
  link.host->request_async(kLaserRange, payload,
                           [&](const session::AckResult& r) { results.add(r); });
  link.host->stop();
  ASSERT_EQ(results.size(), 2u);  // stop() returns after every callback ran
  for (const session::AckResult& r : results.items()) {
    EXPECT_FALSE(r.received);
    EXPECT_NE(r.message.find("session stopped"), std::string::npos) << r.message;
  }
}

TEST(SessionRequests, BlockingRequestFromAnAsyncCallbackFailsInsteadOfDeadlocking) {
  SessionLink link;
  link.pod->set_request_handler(
      kLaserRange, [](const FrameView&) { return std::optional<Payload>(ack_payload(0)); });
  link.start();
  Collector<session::AckResult> inner;
  const Payload payload = ack_payload(0x0100);
  link.host->request_async(kLaserRange, payload, [&](const session::AckResult&) {
    inner.add(link.host->request(protocol::LaserRangeRequest{}));
  });
  ASSERT_TRUE(inner.wait_for_count(1));
  EXPECT_FALSE(inner.items()[0].sent);
  EXPECT_NE(inner.items()[0].message.find("request_async"), std::string::npos);
}

TEST(SessionRequests, ConcurrentRequestsFromSeveralThreads) {
  SessionLink link(host_options(5000ms, 1));
  const std::vector<protocol::MessageId> ids = {0x000400, 0x000018, 0x000105, 0x000304};
  for (protocol::MessageId id : ids) {
    link.pod->set_request_handler(id, [id](const FrameView& f) {
      // Echo the request's first byte after the code, so each caller can check it got its own.
      return std::optional<Payload>(ack_payload(0, {static_cast<uint8_t>(id), f.payload[0]}));
    });
  }
  link.start();
  constexpr int kThreads = 8;
  constexpr int kPerThread = 25;
  std::atomic<int> good{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < kPerThread; ++i) {
        const protocol::MessageId id = ids[(t + i) % ids.size()];
        const uint8_t payload[] = {static_cast<uint8_t>(t * kPerThread + i), 0x00};
        const session::AckResult r = link.host->request_raw(id, payload, 2);
        // Same-id requests are serialised, so the echo must be this caller's.
        if (r.ok() && r.payload.size() == 4 && r.payload[2] == static_cast<uint8_t>(id) &&
            r.payload[3] == payload[0]) {
          ++good;
        }
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(good.load(), kThreads * kPerThread);
  const session::SessionStats s = link.host->stats();
  EXPECT_EQ(s.requests, static_cast<uint64_t>(kThreads * kPerThread));
  EXPECT_EQ(s.acks, s.requests);
  EXPECT_EQ(s.late_acks, 0u);
  EXPECT_EQ(s.ack_timeouts, 0u);
  EXPECT_EQ(s.frames_sent, s.requests + s.retries);
}

}  // namespace
}  // namespace k40t::test
