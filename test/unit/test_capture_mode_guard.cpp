// CaptureModeGuard: section 3.2.4.1's note (the pod does not answer a photo request in video mode,
// nor a record request in photo mode) turned into a refusal that names the mode, before sending.
#include <gtest/gtest.h>

#include "framed_message.h"
#include "k40t_driver/operations/capture_mode_guard.h"
#include "k40t_driver/protocol/messages/camera_capture.h"
#include "request_with.h"
#include "sim_link_harness.h"

namespace k40t::operations {
namespace {

namespace p = protocol;
using k40t::testing::Framed;
using k40t::testing::plain_ack;
using Clock = CaptureModeGuard::Clock;

Framed camera_in(p::CaptureMode mode) {
  p::CameraSystemStatus camera;
  camera.capture_mode = mode;
  return Framed(camera);
}

TEST(CaptureModeGuard, TheOtherModeIsRefusedWithTheReason) {
  CaptureModeGuard guard;
  const p::CodecOptions codec;
  EXPECT_TRUE(guard.allows(p::CaptureMode::kVideo, "record requests")) << "mode not known yet";
  guard.frame_received(camera_in(p::CaptureMode::kVideo).view, codec);
  EXPECT_TRUE(guard.allows(p::CaptureMode::kVideo, "record requests"));
  const Status photo = guard.allows(p::CaptureMode::kPhoto, "photo requests");
  ASSERT_FALSE(photo);
  EXPECT_EQ(photo.message(),
            "not sent: the camera is in video mode, and in video mode the pod does not answer "
            "photo requests (section 3.2.4.1); switch to photo mode first (reconfigure parameter "
            "camera_mode, 0x000300)");
  guard.frame_received(camera_in(p::CaptureMode::kPhoto).view, codec);
  EXPECT_TRUE(guard.allows(p::CaptureMode::kPhoto, "photo requests"));
  EXPECT_NE(guard.allows(p::CaptureMode::kVideo, "record requests").message().find("photo mode"),
            std::string::npos);
}

// A switch the pod accepted counts at once; a 1 Hz report made before it does not undo it.
TEST(CaptureModeGuard, AnAcceptedSwitchHoldsAgainstAnOlderReport) {
  CaptureModeGuard guard;
  const p::CodecOptions codec;
  const Clock::time_point t0 = Clock::now();
  guard.frame_received(camera_in(p::CaptureMode::kPhoto).view, codec, t0);
  p::CaptureModeRequest video;
  video.mode = p::CaptureMode::kVideo;
  guard.frame_sent(Framed(video).view, codec);
  guard.frame_received(plain_ack(video.kId, p::ResponseCode::kFailure).view, codec, t0);
  EXPECT_FALSE(guard.allows(p::CaptureMode::kVideo, "record requests")) << "refused: still photo";

  guard.frame_sent(Framed(video).view, codec);
  guard.frame_received(plain_ack(video.kId, p::ResponseCode::kOk).view, codec, t0);
  EXPECT_TRUE(guard.allows(p::CaptureMode::kVideo, "record requests"));
  guard.frame_received(camera_in(p::CaptureMode::kPhoto).view, codec, t0 + std::chrono::seconds(1));
  EXPECT_TRUE(guard.allows(p::CaptureMode::kVideo, "record requests"));
  guard.frame_received(camera_in(p::CaptureMode::kPhoto).view, codec, t0 + std::chrono::seconds(2));
  EXPECT_FALSE(guard.allows(p::CaptureMode::kVideo, "record requests")) << "the pod says photo";
}

Framed photo_mode(p::PhotoMode mode) {
  p::CameraSystemStatus camera;
  camera.photo_mode = mode;
  return Framed(camera);
}

// photo_mode_2 (docs/protocol/decisions.md#conventions): under self_timer, photo mode 2 takes one
// photo after the interval and a "stop" has nothing to stop (3.2.4.3: burst mode only); under
// time_lapse it ends the time-lapse. A burst can be stopped under both.
TEST(CaptureModeGuard, AStopInPhotoMode2FollowsTheReading) {
  CaptureModeGuard guard;
  const p::CodecOptions codec;
  EXPECT_TRUE(guard.allows_stop(p::PhotoMode2::kSelfTimer)) << "mode not known yet";
  guard.frame_received(photo_mode(p::PhotoMode::kTimeLapse).view, codec);
  EXPECT_TRUE(guard.allows_stop(p::PhotoMode2::kTimeLapse));
  const Status refused = guard.allows_stop(p::PhotoMode2::kSelfTimer);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.message().find("self-timer"), std::string::npos) << refused.message();
  EXPECT_NE(refused.message().find("photo_mode_2: self_timer"), std::string::npos);
  guard.frame_received(photo_mode(p::PhotoMode::kBurst).view, codec);
  EXPECT_TRUE(guard.allows_stop(p::PhotoMode2::kSelfTimer));
  EXPECT_TRUE(guard.allows_stop(p::PhotoMode2::kTimeLapse));
}

// Against the simulated pod, silent in the other mode as the document says: the guard, given the
// pod's 0x000003, refuses before sending; a photo request sent anyway (the mode not known yet) is
// sent once, goes unanswered, and the text the user gets says why, not only "no ACK".
TEST(CaptureModeGuard, AgainstTheSilentPodTheUserGetsTheReason) {
  sim::testing::SimLink link;
  const p::CodecOptions codec;
  ASSERT_EQ(
      link.send(k40t::testing::request_with(&p::CaptureModeRequest::mode, p::CaptureMode::kVideo)),
      p::ResponseCode::kOk);
  const auto video = link.wait_report<p::CameraSystemStatus>(
      [](const p::CameraSystemStatus& s) { return s.capture_mode == p::CaptureMode::kVideo; });
  ASSERT_TRUE(video);
  CaptureModeGuard guard;
  guard.frame_received(Framed(*video).view, codec);
  const Status refused = guard.allows(p::CaptureMode::kPhoto, "photo requests");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.message().find("in video mode the pod does not answer photo requests"),
            std::string::npos)
      << refused.message();

  const session::AckResult sent_anyway = link.client().request(p::TakePhotoRequest{});
  EXPECT_TRUE(sent_anyway.sent);
  EXPECT_FALSE(sent_anyway.received) << "the pod answered a photo request in video mode";
  EXPECT_EQ(sent_anyway.attempts, 1) << "a photo request is never re-sent blindly";
  const std::string told =
      CaptureModeGuard::unanswered(p::CaptureMode::kPhoto, "photo requests", sent_anyway.message);
  EXPECT_NE(told.find(sent_anyway.message), std::string::npos);
  EXPECT_NE(told.find("in video mode the pod does not answer photo requests (section 3.2.4.1)"),
            std::string::npos)
      << told;
  link.server().with_model([](sim::PodModel& pod) { EXPECT_TRUE(pod.camera().photos().empty()); });
}

}  // namespace
}  // namespace k40t::operations
