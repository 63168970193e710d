// CaptureModeGuard: section 3.2.4.1's note (the pod does not answer a photo request in video mode,
// nor a record request in photo mode) turned into a refusal that names the mode, before sending.
#include <gtest/gtest.h>

#include "framed_message.h"
#include "k40t_driver/operations/capture_mode_guard.h"
#include "k40t_driver/protocol/messages/camera_capture.h"

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

}  // namespace
}  // namespace k40t::operations
