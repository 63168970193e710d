// Requests whose repeat would repeat an action (protocol/repeat_safety.h: a photo, a recording, a
// zoom step) are written once, however late their ACK: a retry after ack_timeout used to take two
// or three photos. The ACK is waited for as long as every attempt would have taken.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/repeat_safety.h"
#include "session_test_link.h"

namespace k40t::test {
namespace {

using namespace std::chrono_literals;
using protocol::FrameView;
using protocol::Payload;

// A host with attempts of `timeout` (three in all) and a pod that answers each request `id`
// `delay` after it came (on a thread of its own, as a pod that first asks for GPS would), or never
// when `delay` is negative.
session::SessionOptions host_with(std::chrono::milliseconds timeout, protocol::CalibrationEnd end) {
  session::SessionOptions o = host_options(timeout, 2);
  o.codec.conventions.calibration_end = end;
  return o;
}

struct LatePod {
  Collector<protocol::FrameHeader> seen;
  std::vector<std::thread> answers;
  SessionLink link;  // last: stopped before what its handlers use goes

  LatePod(std::chrono::milliseconds timeout, protocol::MessageId id,
          std::chrono::milliseconds delay,
          protocol::CalibrationEnd end = protocol::CalibrationEnd::kAuto)
      : link(host_with(timeout, end)) {
    link.pod->set_request_handler(id, [this, delay](const FrameView& f) -> std::optional<Payload> {
      seen.add(f.header);
      if (delay.count() < 0) return std::nullopt;
      answers.emplace_back([this, header = f.header, delay] {
        std::this_thread::sleep_for(delay);
        const Payload ok = ack_payload(0);
        link.pod->send_ack(header, ok.data(), ok.size);
      });
      return std::nullopt;
    });
    link.start();
  }
  ~LatePod() {
    for (std::thread& t : answers) t.join();
  }
};

TEST(SessionSentOnce, ALatePhotoAckIsWaitedForWithoutASecondPhoto) {
  LatePod pod(40ms, protocol::TakePhotoRequest::kId, 90ms);  // 120 ms in all, the ACK at 90 ms
  const session::AckResult r = pod.link.host->request(protocol::TakePhotoRequest{});
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.attempts, 1);
  std::this_thread::sleep_for(100ms);  // a retry, had there been one, would have arrived
  EXPECT_EQ(pod.seen.items().size(), 1u) << "one photo request on the wire";
  EXPECT_EQ(pod.link.host->stats().retries, 0u);
}

TEST(SessionSentOnce, NoAckSaysItWasNotRepeatedAndMayHaveHappened) {
  LatePod pod(20ms, protocol::RecordRequest::kId, -1ms);
  const auto start = std::chrono::steady_clock::now();
  const session::AckResult r = pod.link.host->request(protocol::RecordRequest{});
  EXPECT_GE(std::chrono::steady_clock::now() - start, 60ms) << "as long as three attempts";
  EXPECT_TRUE(r.sent);
  EXPECT_FALSE(r.received);
  EXPECT_EQ(r.code, protocol::ResponseCode::kTimeout);
  EXPECT_EQ(r.attempts, 1);
  EXPECT_NE(r.message.find("no ACK for record (0x000303) within 60 ms; not sent again"),
            std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("the pod may have done it"), std::string::npos) << r.message;
  EXPECT_EQ(pod.seen.items().size(), 1u);
  EXPECT_EQ(pod.link.host->stats().ack_timeouts, 1u);
}

TEST(SessionSentOnce, AZoomStepIsSentOnceAContinuousZoomIsRetried) {
  LatePod pod(20ms, protocol::ContinuousZoomRequest::kId, -1ms);
  protocol::ContinuousZoomRequest step;
  step.command = protocol::ZoomCommand::kStepIn;
  EXPECT_EQ(pod.link.host->request(step).attempts, 1);
  protocol::ContinuousZoomRequest zoom;
  zoom.command = protocol::ZoomCommand::kZoomIn;  // a state: the same again does no harm
  EXPECT_EQ(pod.link.host->request(zoom).attempts, 3);
  ASSERT_TRUE(pod.seen.wait_for_count(4));
}

// A calibration is sent once too (a repeat starts it again); a pod whose calibrations end with
// their ACK (calibration_end: ack, or auto until known) answers when done, seconds later: that
// ACK is awaited up to kCalibrationAckWait. Under status the usual wait ends it.
TEST(SessionSentOnce, ACalibrationsLateAckIsAwaitedUnlessItsEndIsAStatus) {
  LatePod ack_pod(20ms, protocol::GimbalDriftCalibrationRequest::kId, 300ms);
  const session::AckResult done =
      ack_pod.link.host->request(protocol::GimbalDriftCalibrationRequest{});
  EXPECT_TRUE(done.ok()) << done.message;
  EXPECT_EQ(done.attempts, 1);
  LatePod status_pod(20ms, protocol::GimbalDriftCalibrationRequest::kId, 300ms,
                     protocol::CalibrationEnd::kStatus);
  const session::AckResult late =
      status_pod.link.host->request(protocol::GimbalDriftCalibrationRequest{});
  EXPECT_FALSE(late.received);
  EXPECT_EQ(late.attempts, 1);
  EXPECT_NE(late.message.find("within 60 ms; not sent again"), std::string::npos) << late.message;
}

// Section 3.2.4.6: byte 1 of 0x000306 is the command, 3 / 4 one step in / out.
TEST(RepeatSafety, TheActionsAreListedAndNothingElse) {
  const uint8_t step_out[] = {0x04};
  const uint8_t stop[] = {0x02};
  EXPECT_FALSE(protocol::repeat_safe(0x000302, nullptr, 0));  // take photo
  EXPECT_FALSE(protocol::repeat_safe(0x000303, nullptr, 0));  // record
  EXPECT_FALSE(protocol::repeat_safe(0x000307, nullptr, 0));  // precise re-shoot
  EXPECT_FALSE(protocol::repeat_safe(0x000306, step_out, 1));
  EXPECT_TRUE(protocol::repeat_safe(0x000306, stop, 1));
  EXPECT_TRUE(protocol::repeat_safe(0x000304, nullptr, 0));   // zoom to a ratio
  EXPECT_TRUE(protocol::repeat_safe(0x000012, nullptr, 0));   // gimbal to an angle
  EXPECT_FALSE(protocol::repeat_safe(0x000013, nullptr, 0));  // drift calibration
  EXPECT_FALSE(protocol::repeat_safe(0x00002E, nullptr, 0));  // linear calibration
  EXPECT_FALSE(protocol::repeat_safe(0x000031, nullptr, 0));  // accelerometer calibration
  protocol::Conventions c;
  EXPECT_EQ(protocol::done_ack_wait(0x000013, c), protocol::kCalibrationAckWait);  // auto
  c.calibration_end = protocol::CalibrationEnd::kStatus;
  EXPECT_EQ(protocol::done_ack_wait(0x000013, c).count(), 0);
  EXPECT_EQ(protocol::done_ack_wait(0x000302, c).count(), 0);
}

}  // namespace
}  // namespace k40t::test
