// The simulated pod's RTSP server against the video client, both back-ends, over real sockets on
// 127.0.0.1: stamped frames arrive, the frame size follows the image mode, the grabber notices a
// dead or frozen stream within its read timeout and reconnects when the stream is back.
#include <gtest/gtest.h>

#include <netinet/in.h>
#include <sys/socket.h>

#include <atomic>
#include <mutex>
#include <optional>

#include "k40t_driver/sim/video/frame_stamp.h"
#include "k40t_driver/sim/video/rtsp_stream_server.h"
#include "k40t_driver/video/capture_open.h"
#include "k40t_driver/video/frame_grabber.h"
#include "video_stream_fixture.h"
#include "video_test_support.h"

namespace k40t::video {
namespace {

using sim::video::ImageMode;
using sim::video::RtspServerOptions;
using sim::video::RtspStreamServer;
using std::chrono::milliseconds;
using std::chrono::seconds;
using testing::Stream;
using testing::wait_until;

CaptureOptions options_for(const std::string& url, Backend backend) {
  CaptureOptions o;
  o.url = url;
  o.backend = backend;
  o.read_timeout_s = 1.0;
  o.open_timeout_s = 4.0;  // FFmpeg probes the stream while opening: slow on a busy machine
  return o;
}

std::optional<sim::video::FrameStamp> stamp_of(const GrabbedFrame& frame) {
  return sim::video::read_frame_stamp(to_bgr(frame));
}

class VideoRtsp : public ::testing::TestWithParam<Backend> {};

TEST_P(VideoRtsp, StampedFramesArriveInOrderAndFresh) {
  Stream stream(ImageMode::kThermal);
  FrameGrabber grabber(options_for(stream.url(), GetParam()));
  grabber.start();
  uint64_t last = 0;
  std::optional<uint32_t> previous_counter;
  int stamped = 0;
  for (int i = 0; i < 20; ++i) {
    auto frame = grabber.wait_newer(last, seconds(i == 0 ? 10 : 5));
    ASSERT_TRUE(frame) << grabber.stats().last_error;
    last = frame->sequence;
    EXPECT_EQ(frame->size, cv::Size(640, 512));
    EXPECT_EQ(frame->i420, GetParam() == Backend::kGStreamer);
    const auto stamp = stamp_of(*frame);
    if (!stamp) continue;
    ++stamped;
    if (previous_counter) {
      EXPECT_GT(stamp->counter, *previous_counter);
    }
    previous_counter = stamp->counter;
    EXPECT_GE(frame->received_us, stamp->render_time_us);
    EXPECT_LT(frame->received_us - stamp->render_time_us, 2'000'000);
  }
  EXPECT_GE(stamped, 15);
  EXPECT_EQ(grabber.stats().reconnects, 0u);
}

TEST_P(VideoRtsp, TheFrameSizeFollowsTheImageMode) {
  Stream stream(ImageMode::kThermal);
  FrameGrabber grabber(options_for(stream.url(), GetParam()));
  grabber.start();
  auto first = grabber.wait_newer(0, seconds(10));
  ASSERT_TRUE(first);
  EXPECT_EQ(first->size, cv::Size(640, 512));
  stream.set_mode(ImageMode::kVisible);
  // OpenCV 4.6's FFmpeg back-end does not follow a size change by itself (frame_grabber.h).
  if (GetParam() == Backend::kFFmpeg) grabber.restart();
  uint64_t last = first->sequence;
  const auto switched = wait_until(
      [&] {
        auto frame = grabber.wait_newer(last, milliseconds(100));
        if (!frame) return false;
        last = frame->sequence;
        return frame->size == cv::Size(1920, 1080) && stamp_of(*frame).has_value();
      },
      seconds(5));
  EXPECT_TRUE(switched);
}

TEST_P(VideoRtsp, AStoppedServerIsNoticedAndTheStreamComesBack) {
  auto stream = std::make_unique<Stream>(ImageMode::kThermal);
  const std::string url = stream->url();
  const int port = std::stoi(url.substr(url.rfind(':') + 1));
  FrameGrabber grabber(options_for(url, GetParam()));
  grabber.start();
  ASSERT_TRUE(grabber.wait_newer(0, seconds(10)));
  stream.reset();
  const auto noticed = wait_until([&] { return !grabber.stats().streaming; }, seconds(3));
  ASSERT_TRUE(noticed);
  EXPECT_LT(noticed->count(), 1.5);
  const uint64_t before = grabber.stats().frames;
  stream = std::make_unique<Stream>(ImageMode::kThermal, port);
  const auto back = wait_until([&] { return grabber.stats().frames > before + 5; }, seconds(10));
  ASSERT_TRUE(back) << grabber.stats().last_error;
  EXPECT_GE(grabber.stats().reconnects, 1u);
}

TEST_P(VideoRtsp, AFrozenServerEndsTheReadWithinTheReadTimeout) {
  testing::SimStreamProcess sim({"--mode", "0", "--key-interval", "10"});
  ASSERT_FALSE(sim.url().empty());
  FrameGrabber grabber(options_for(sim.url(), GetParam()));
  grabber.start();
  ASSERT_TRUE(grabber.wait_newer(0, seconds(10))) << grabber.stats().last_error;
  sim.freeze();
  const auto noticed = wait_until([&] { return !grabber.stats().streaming; }, seconds(4));
  ASSERT_TRUE(noticed) << "the read never returned";
  EXPECT_LT(noticed->count(), 1.0 + 0.8);  // read_timeout plus scheduling slack
  EXPECT_GE(grabber.stats().read_errors, 1u);
  // The grabber goes first (declared last), then `sim` ends the frozen server without thawing it.
}

INSTANTIATE_TEST_SUITE_P(Backends, VideoRtsp,
                         ::testing::Values(Backend::kGStreamer, Backend::kFFmpeg),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(VideoRtspServer, ABusyPortOrBadOptionsAreNamed) {
  Stream first(ImageMode::kThermal);
  const std::string url = first.url();
  RtspServerOptions options;
  options.port = std::stoi(url.substr(url.rfind(':') + 1));
  auto second = RtspStreamServer::start(options, {});
  ASSERT_FALSE(second);
  EXPECT_NE(second.error().find(std::to_string(options.port)), std::string::npos) << second.error();
  RtspServerOptions bad;
  bad.path = "live";
  EXPECT_NE(RtspStreamServer::start(bad, {}).error().find("path 'live'"), std::string::npos);
  bad = {};
  bad.fps = 0;
  EXPECT_NE(RtspStreamServer::start(bad, {}).error().find("frame rate 0"), std::string::npos);
}

TEST(VideoCapture, ASilentServerFailsTheOpenWithinTheOpenTimeout) {
  // Accepts connections (the kernel does) and never answers.
  const int listener = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(listen(listener, 4), 0);
  socklen_t size = sizeof address;
  getsockname(listener, reinterpret_cast<sockaddr*>(&address), &size);
  const std::string url = "rtsp://127.0.0.1:" + std::to_string(ntohs(address.sin_port)) + "/live";
  for (Backend backend : {Backend::kGStreamer, Backend::kFFmpeg}) {
    CaptureOptions o = options_for(url, backend);
    o.open_timeout_s = 1.0;  // the RTSP handshake never gets an answer: no probing to wait for
    const auto start = std::chrono::steady_clock::now();
    auto capture = open_capture(o);
    const double took =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_FALSE(capture) << to_string(backend);
    if (!capture) {
      EXPECT_NE(capture.error().find(url), std::string::npos);
    }
    EXPECT_LT(took, 3.0) << to_string(backend);
  }
  close(listener);
}

}  // namespace
}  // namespace k40t::video
