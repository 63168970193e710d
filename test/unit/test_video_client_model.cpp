// The video client's pure parts: options, stamps, intrinsics under zoom, what a frame shows
// (video/capture_options.h, stamp_estimator.h, intrinsics.h, stream_view.h).
#include <gtest/gtest.h>

#include "k40t_driver/video/capture_options.h"
#include "k40t_driver/video/intrinsics.h"
#include "k40t_driver/video/stamp_estimator.h"
#include "k40t_driver/video/stream_view.h"

namespace k40t::video {
namespace {

TEST(CaptureOptions, NamesParseAndBadOnesAreNamed) {
  EXPECT_EQ(parse_backend("gstreamer").value(), Backend::kGStreamer);
  EXPECT_EQ(parse_backend("ffmpeg").value(), Backend::kFFmpeg);
  EXPECT_NE(parse_backend("vlc").error().find("'vlc'"), std::string::npos);
  EXPECT_EQ(parse_transport("udp").value(), RtspTransport::kUdp);
  EXPECT_NE(parse_transport("http").error().find("tcp, udp"), std::string::npos);
}

TEST(CaptureOptions, UrlsAndTimeoutsAreChecked) {
  CaptureOptions ok;
  EXPECT_TRUE(validate(ok));
  for (const char* url : {"http://1.2.3.4/x", "rtsp://", "rtsp:///live", "rtsp://a b/live",
                          "rtsp://host/x ! fakesink", "rtsp://h/\"x"}) {
    CaptureOptions o;
    o.url = url;
    const Status s = validate(o);
    EXPECT_FALSE(s) << url;
    EXPECT_NE(s.message().find("video URL"), std::string::npos) << s.message();
  }
  CaptureOptions slow;
  slow.read_timeout_s = 0;
  EXPECT_NE(validate(slow).message().find("read_timeout"), std::string::npos);
}

TEST(CaptureOptions, TheGStreamerPipelineIsLowLatencyAndGuarded) {
  CaptureOptions o;
  o.url = "rtsp://127.0.0.1:8554/live/single";
  o.transport = RtspTransport::kUdp;
  o.read_timeout_s = 1.5;
  const std::string pipeline = gstreamer_pipeline(o);
  EXPECT_NE(pipeline.find("location=\"rtsp://127.0.0.1:8554/live/single\""), std::string::npos);
  EXPECT_NE(pipeline.find("latency=0"), std::string::npos);
  EXPECT_NE(pipeline.find("protocols=udp"), std::string::npos);
  EXPECT_NE(pipeline.find("k40tstallguard timeout=1500"), std::string::npos);
  EXPECT_NE(pipeline.find("max-buffers=1 drop=true sync=false"), std::string::npos);
  EXPECT_EQ(ffmpeg_capture_options(o),
            "rtsp_transport;udp|fflags;nobuffer|flags;low_delay|max_delay;0");
}

TEST(StampEstimator, WithoutPresentationTimesItSubtractsTheLatency) {
  StampOptions o;
  o.latency_s = 0.05;
  StampEstimator e(o);
  EXPECT_EQ(e.stamp(1'000'000, std::nullopt), 950'000);
  EXPECT_EQ(e.stamp(1'040'000, std::nullopt), 990'000);
  // Off by default: presentation times given are not used.
  EXPECT_EQ(e.stamp(2'000'000, 10.0), 1'950'000);
  EXPECT_EQ(e.stamp(2'050'000, 10.033), 2'000'000);
}

TEST(StampEstimator, PresentationTimesTakeOutReceptionJitter) {
  StampOptions o;
  o.latency_s = 0.01;
  o.use_presentation_time = true;
  StampEstimator e(o);
  // Frames every 33.333 ms; reception delayed by 5, 20, 5, 12 ms.
  const double pts[] = {1000, 1033.333, 1066.667, 1100};
  const int64_t delay[] = {5000, 20000, 5000, 12000};
  const int64_t base = 50'000'000;
  int64_t stamps[4];
  for (int i = 0; i < 4; ++i) {
    const int64_t received = base + static_cast<int64_t>(pts[i] * 1000) + delay[i];
    stamps[i] = e.stamp(received, pts[i]);
    EXPECT_LE(stamps[i], received - 10000);
  }
  // After the first frame the least-delayed one (5 ms) sets the offset for all of them.
  EXPECT_NEAR(stamps[1] - stamps[0], 33333, 2);
  EXPECT_NEAR(stamps[3] - stamps[2], 33333, 2);
  EXPECT_NEAR(stamps[2], base + 1066667 + 5000 - 10000, 2);
}

TEST(StampEstimator, APresentationTimeGoingBackRestartsTheMapping) {
  StampOptions o;
  o.use_presentation_time = true;
  StampEstimator e(o);
  e.stamp(10'000'000, 100.0);                   // offset 9.9 s
  const int64_t s = e.stamp(20'000'000, 50.0);  // a new stream: offset 19.95 s
  EXPECT_EQ(s, 20'000'000);
}

TEST(Intrinsics, OpticalZoomScalesFocalLengthsAboutThePrincipalPoint) {
  Intrinsics in = ideal_pinhole(1000, 1920, 1080);
  in.K[2] = 950;  // a calibrated principal point off centre
  const Intrinsics out = zoom_optical(in, 3);
  EXPECT_DOUBLE_EQ(out.K[0], 3000);
  EXPECT_DOUBLE_EQ(out.K[4], 3000);
  EXPECT_DOUBLE_EQ(out.K[2], 950);
  EXPECT_DOUBLE_EQ(out.P[0], 3000);
  EXPECT_DOUBLE_EQ(out.P[5], 3000);
}

TEST(Intrinsics, DigitalZoomCropsAboutTheImageCentre) {
  Intrinsics in = ideal_pinhole(1000, 640, 512);
  in.K[2] = 329.5;  // 10 px right of the centre
  in.P[2] = 329.5;
  const Intrinsics out = zoom_digital(in, 2);
  EXPECT_DOUBLE_EQ(out.K[0], 2000);
  EXPECT_DOUBLE_EQ(out.K[2], 339.5);  // the offset doubles
  EXPECT_DOUBLE_EQ(out.K[5], 255.5);
  EXPECT_DOUBLE_EQ(out.P[2], 339.5);
}

TEST(Intrinsics, ResizingMapsPixelEdgesToPixelEdges) {
  const Intrinsics in = ideal_pinhole(1500, 1920, 1080);
  const Intrinsics out = resized(in, 1280, 720);
  EXPECT_EQ(out.width, 1280);
  EXPECT_NEAR(out.K[0], 1000, 1e-9);
  EXPECT_NEAR(out.K[2], 639.5, 1e-9);
  EXPECT_NEAR(out.K[5], 359.5, 1e-9);
}

TEST(Intrinsics, APanelPlacedInAFrame) {
  const Intrinsics in = ideal_pinhole(1600, 1920, 1080);
  const Intrinsics out = placed(in, 0.5, 0, 270, 1920, 1080);
  EXPECT_NEAR(out.K[0], 800, 1e-9);
  EXPECT_NEAR(out.K[2], 479.5, 1e-9);  // the panel's own centre
  EXPECT_NEAR(out.K[5], 270 + 269.5, 1e-9);
  EXPECT_EQ(out.width, 1920);
}

TEST(Intrinsics, TheThermalImageInTheSplitScreensRightPanel) {
  // 640x512 scaled to the 960 px wide right half of 1920x1080: 960x768 at (960, 156).
  const Intrinsics thermal = ideal_pinhole(1000, 640, 512);
  const SplitLayout layout = split_layout({1920, 1080});
  ASSERT_EQ(layout.thermal, cv::Rect(960, 156, 960, 768));
  const Intrinsics out = in_panel(thermal, layout.thermal, {1920, 1080});
  EXPECT_NEAR(out.K[0], 1500, 1e-9);  // x 1.5
  EXPECT_NEAR(out.K[4], 1500, 1e-9);
  EXPECT_NEAR(out.K[2], 960 + 479.5, 1e-9);  // the panel's centre, pixel centres at integers
  EXPECT_NEAR(out.K[5], 156 + 383.5, 1e-9);
  EXPECT_EQ(out.width, 1920);
  EXPECT_EQ(out.height, 1080);
}

TEST(StreamView, ThermalBySizeVisibleOrSplitByMode) {
  const cv::Size thermal(640, 512);
  const cv::Size hd(1920, 1080);
  EXPECT_EQ(stream_view(0, thermal, Lens::kTele).lens, Lens::kThermal);
  EXPECT_EQ(stream_view(5, thermal, Lens::kTele).lens, Lens::kThermal);  // stale mode
  EXPECT_EQ(stream_view(0, hd, Lens::kTele).lens, Lens::kTele);          // stale mode
  EXPECT_EQ(stream_view(std::nullopt, hd, Lens::kTele).lens, Lens::kTele);
  EXPECT_EQ(stream_view(6, hd, Lens::kWide).lens, Lens::kWide);
  const StreamView split = stream_view(7, hd, Lens::kWide);
  EXPECT_TRUE(split.split);
  EXPECT_EQ(split.lens, Lens::kTele);
  EXPECT_FALSE(stream_view(7, thermal, Lens::kTele).split);
}

}  // namespace
}  // namespace k40t::video
