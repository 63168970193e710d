// The simulator playing the document's open readings (docs/protocol/decisions.md#conventions)
// where its model, not only its encoding, changes: shutters beyond 16 bits of microseconds, and
// photo mode 2 as a self-timer. The bytes of each reading are test_convention_readings.cpp's.
#include <gtest/gtest.h>

#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "sim_pod_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using namespace testing;  // PodHarness, request_with, ResponseCode

// 1/4 s = 250 000 us = 0x3D090. Before the fix the simulator cast it to uint16 and sent 0xD090
// (53 392 us, "0.053 s") under every reading.
TEST(SimConventions, ASlowShutterIsSentAsEachShutterReadingSays) {
  for (const auto& [field, raw] : {std::pair{p::ShutterField::kMicroseconds, 0xFFFF},
                                   std::pair{p::ShutterField::kMicrosecondsWrapped, 0xD090},
                                   std::pair{p::ShutterField::kHundredMicroseconds, 2500}}) {
    p::CodecOptions codec;
    codec.conventions.shutter_field = field;
    PodHarness h({}, codec);
    ASSERT_EQ(h.send(request_with(&p::VisibleShutterRequest::shutter, p::Shutter::k1_4)),
              ResponseCode::kOk);
    EXPECT_EQ(h.report<p::VisibleStatus>().shutter_us, raw);
  }
}

p::TakePhotoRequest photo(p::PhotoAction action = p::PhotoAction::kStart) {
  p::TakePhotoRequest request;
  request.lens = p::PhotoLensMode::kVisible;
  request.action = action;
  return request;
}

// Photo mode 2 (3.2.4.2): a self-timer takes one photo the interval after the request, and
// "stop" is for burst mode only (3.2.4.3); a time-lapse repeats until stopped.
TEST(SimConventions, PhotoMode2AsASelfTimer) {
  PodConfig config;
  config.camera.self_timer = true;
  PodHarness h(config);
  p::PhotoSettingsRequest settings;
  settings.photo_mode = p::PhotoMode::kTimeLapse;
  settings.time_lapse_interval_s = 5;
  settings.burst_count = 3;
  ASSERT_EQ(h.send(settings), ResponseCode::kOk);
  ASSERT_EQ(h.send(photo()), ResponseCode::kOk);
  h.run(4.5);
  EXPECT_EQ(h.pod.camera().photos().size(), 0u);
  EXPECT_EQ(h.send(photo(p::PhotoAction::kStop)), ResponseCode::kFailure);
  h.run(16.0);
  EXPECT_EQ(h.pod.camera().photos().size(), 1u);
  EXPECT_EQ(h.send(photo()), ResponseCode::kOk);  // the camera is free again

  PodHarness lapse;  // the default reading
  ASSERT_EQ(lapse.send(settings), ResponseCode::kOk);
  ASSERT_EQ(lapse.send(photo()), ResponseCode::kOk);
  lapse.run(11.0);
  EXPECT_GE(lapse.pod.camera().photos().size(), 2u);
  EXPECT_EQ(lapse.send(photo(p::PhotoAction::kStop)), ResponseCode::kOk);
}

}  // namespace
}  // namespace k40t::sim
