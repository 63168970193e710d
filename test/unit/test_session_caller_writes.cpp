// Who writes a blocking request (session/request_tracker.h): the caller itself when nothing for
// its id is outstanding or queued (one thread hand-over less before the wire: the settings
// services' round trip), the tracker's thread otherwise; a stop during the caller's write still
// ends the call; and its ACK completes it on the I/O thread, without the tracker's thread.
#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <thread>

#include "k40t_driver/protocol/messages/laser.h"
#include "session_test_link.h"

namespace k40t::test {
namespace {

using namespace std::chrono_literals;
using protocol::FrameView;
using protocol::Payload;

// Any request the pod-role session answers by its handler; two payload bytes of its own.
constexpr protocol::MessageId kLaserRange = protocol::LaserRangeRequest::kId;
const uint8_t kPayload[] = {0x01, 0x00};

TEST(SessionCallerWrites, ARequestWithNothingAheadIsWrittenByTheCaller) {
  SessionLink link;
  link.pod->set_request_handler(
      kLaserRange, [](const FrameView&) { return std::optional<Payload>(ack_payload(0)); });
  std::thread::id writer;
  link.host->on_frame_sent([&writer](const FrameView&) { writer = std::this_thread::get_id(); });
  link.start();
  const session::AckResult r = link.host->request_raw(kLaserRange, kPayload, sizeof kPayload);
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.attempts, 1);
  EXPECT_EQ(writer, std::this_thread::get_id());
  EXPECT_EQ(link.host->stats().requests, 1u);
}

TEST(SessionCallerWrites, ARequestQueuedBehindAnotherIsWrittenByTheTrackersThread) {
  SessionLink link(host_options(10000ms, 0));
  Collector<protocol::FrameHeader> pod_requests;
  link.pod->set_request_handler(kLaserRange, [&](const FrameView& f) -> std::optional<Payload> {
    pod_requests.add(f.header);
    return std::nullopt;  // answered by hand below
  });
  Collector<std::thread::id> writers;
  link.host->on_frame_sent(
      [&writers](const FrameView&) { writers.add(std::this_thread::get_id()); });
  link.start();
  std::promise<std::thread::id> first_caller;
  std::thread first([&] {
    first_caller.set_value(std::this_thread::get_id());
    link.host->request_raw(kLaserRange, kPayload, sizeof kPayload);
  });
  ASSERT_TRUE(pod_requests.wait_for_count(1));
  std::thread second([&] { link.host->request_raw(kLaserRange, kPayload, sizeof kPayload); });
  std::this_thread::sleep_for(100ms);  // queued behind the first
  const Payload ok = ack_payload(0);
  ASSERT_TRUE(link.pod->send_ack(pod_requests.items()[0], ok.data(), ok.size));
  ASSERT_TRUE(pod_requests.wait_for_count(2));
  ASSERT_TRUE(link.pod->send_ack(pod_requests.items()[1], ok.data(), ok.size));
  first.join();
  second.join();
  ASSERT_TRUE(writers.wait_for_count(2));
  EXPECT_EQ(writers.items()[0], first_caller.get_future().get());
  EXPECT_NE(writers.items()[1], writers.items()[0]);
  EXPECT_NE(writers.items()[1], std::this_thread::get_id());
}

TEST(SessionCallerWrites, AStopDuringTheCallersWriteEndsTheCall) {
  SessionLink link(host_options(60000ms, 0));
  std::promise<void> writing, stopped;
  std::shared_future<void> stopped_future = stopped.get_future().share();
  std::atomic<bool> first{true};
  link.host->on_frame_sent([&](const FrameView&) {
    if (!first.exchange(false)) return;
    writing.set_value();
    stopped_future.wait();  // the write returns only after stop() has
  });
  link.start();
  std::future<session::AckResult> call = std::async(std::launch::async, [&] {
    return link.host->request_raw(kLaserRange, kPayload, sizeof kPayload);
  });
  writing.get_future().wait();
  link.host->stop();
  stopped.set_value();
  const session::AckResult r = call.get();
  EXPECT_FALSE(r.received);
  EXPECT_NE(r.message.find("session stopped"), std::string::npos) << r.message;
}

TEST(SessionCallerWrites, ItsAckCompletesABlockingRequestWhileTheSessionsThreadIsBusy) {
  constexpr protocol::MessageId kGimbalVersion = 0x000018;
  SessionLink link;
  link.pod->set_request_handler(
      kLaserRange, [](const FrameView&) { return std::optional<Payload>(ack_payload(0)); });
  link.pod->set_request_handler(
      kGimbalVersion, [](const FrameView&) { return std::optional<Payload>(ack_payload(0)); });
  link.start();
  // An asynchronous request's callback holds the session's thread until the blocking one is done.
  std::promise<void> in_callback, release;
  std::shared_future<void> released = release.get_future().share();
  link.host->request_async(kGimbalVersion, ack_payload(0), [&](const session::AckResult&) {
    in_callback.set_value();
    released.wait();
  });
  in_callback.get_future().wait();
  std::future<session::AckResult> call = std::async(std::launch::async, [&] {
    return link.host->request_raw(kLaserRange, kPayload, sizeof kPayload);
  });
  const bool completed = call.wait_for(5s) == std::future_status::ready;
  release.set_value();
  ASSERT_TRUE(completed) << "the blocking request waited for the session's thread";
  EXPECT_TRUE(call.get().ok());
}

}  // namespace
}  // namespace k40t::test
