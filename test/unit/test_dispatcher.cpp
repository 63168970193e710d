// The Dispatcher on its own (no I/O), as replay mode and the tools use it. Frames are written by
// hand from the document; checksums by test/data/frame_crc.py.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/session/dispatcher.h"

namespace k40t::session {
namespace {

using protocol::FrameView;

// ACK 0x010400 (section 3.2.5.1) camera 0x04/0x01 -> host 0x01/0x01, SEQ 0: code 0x0000 and
// distance 0x007B = 12.3 m, big-endian (docs/protocol/decisions.md#a2).
const std::vector<uint8_t> kLaserAck = {0xFD, 0x04, 0x01, 0x01, 0x00, 0x04, 0x01, 0x00,
                                        0x04, 0x01, 0x00, 0x00, 0x00, 0x7B, 0x82, 0x9E};
// The same ACK with only the response code 0x0008 busy (the decoder's minimum), SEQ 1.
const std::vector<uint8_t> kLaserBusyAck = {0xFD, 0x02, 0x01, 0x01, 0x01, 0x04, 0x01,
                                            0x00, 0x04, 0x01, 0x00, 0x08, 0x49, 0x74};
// A one-byte ACK payload, shorter than any ACK decoder accepts, SEQ 2.
const std::vector<uint8_t> kLaserTruncatedAck = {0xFD, 0x01, 0x01, 0x01, 0x02, 0x04, 0x01,
                                                 0x00, 0x04, 0x01, 0x20, 0x0A, 0x0B};

Dispatcher make_dispatcher() {
  return Dispatcher(protocol::CrcCoverage::kAuto, protocol::CodecOptions{});
}

TEST(Dispatcher, RoutesAFrameFedByteByByte) {
  Dispatcher d = make_dispatcher();
  std::vector<std::string> order;
  std::vector<double> distances;
  d.on_frame([&](const FrameView& f) { order.push_back("frame " + std::to_string(f.size)); });
  d.on<protocol::LaserRangeAck>([&](const protocol::LaserRangeAck& a, const FrameView&) {
    order.push_back("typed");
    distances.push_back(a.distance_m);
  });
  for (uint8_t b : kLaserAck) d.feed(&b, 1);
  EXPECT_EQ(order, (std::vector<std::string>{"frame 16", "typed"}));  // raw first, then typed
  ASSERT_EQ(distances.size(), 1u);
  EXPECT_DOUBLE_EQ(distances[0], 12.3);
  EXPECT_EQ(d.parser_stats().frames_good, 1u);
  EXPECT_EQ(d.stats().parser.frames_good, 1u);
  EXPECT_EQ(d.stats().parser.bytes_received, kLaserAck.size());
}

TEST(Dispatcher, SeveralHandlersForOneIdAllRun) {
  Dispatcher d = make_dispatcher();
  int calls = 0;
  for (int i = 0; i < 3; ++i) {
    d.on<protocol::LaserRangeAck>(
        [&](const protocol::LaserRangeAck&, const FrameView&) { ++calls; });
  }
  d.feed_frame(kLaserAck.data(), kLaserAck.size());
  EXPECT_EQ(calls, 3);
}

TEST(Dispatcher, ShortPayloadIsADecodeErrorNotACrash) {
  Dispatcher d = make_dispatcher();
  int typed = 0;
  std::vector<std::string> errors;
  d.on<protocol::LaserRangeAck>([&](const protocol::LaserRangeAck&, const FrameView&) { ++typed; });
  d.on_decode_error([&](const FrameView& f, const std::string& e) {
    EXPECT_EQ(f.header.message_id, 0x010400u);
    errors.push_back(e);
  });
  d.feed_frame(kLaserBusyAck.data(), kLaserBusyAck.size());  // 2 bytes: decodes (code only)
  d.feed_frame(kLaserTruncatedAck.data(), kLaserTruncatedAck.size());
  EXPECT_EQ(typed, 1);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("laser_range_ack (0x010400)"), std::string::npos) << errors[0];
  EXPECT_EQ(d.decode_errors(), 1u);
  EXPECT_EQ(d.stats().decode_errors, 1u);
  EXPECT_EQ(d.stats().parser.frames_good, 2u);
}

TEST(Dispatcher, FramesWithoutATypedHandlerAreNotDecoded) {
  Dispatcher d = make_dispatcher();
  int frames = 0;
  d.on_frame([&](const FrameView&) { ++frames; });
  d.feed_frame(kLaserTruncatedAck.data(), kLaserTruncatedAck.size());
  EXPECT_EQ(frames, 1);
  EXPECT_EQ(d.decode_errors(), 0u);
}

TEST(Dispatcher, ResetDropsAPartialFrame) {
  Dispatcher d = make_dispatcher();
  int frames = 0;
  d.on_frame([&](const FrameView&) { ++frames; });
  d.feed(kLaserAck.data(), 8);
  d.reset();
  d.feed(kLaserAck.data() + 8, kLaserAck.size() - 8);
  EXPECT_EQ(frames, 0);
  d.feed(kLaserAck.data(), kLaserAck.size());
  EXPECT_EQ(frames, 1);
}

TEST(Dispatcher, LocksOntoWholeFrameCoverage) {
  Dispatcher d = make_dispatcher();
  // kLaserAck with whole-frame coverage (STX included), SEQ 0, 1, 2: checksums by frame_crc.py.
  const std::vector<std::vector<uint8_t>> frames = {
      {0xFD, 0x04, 0x01, 0x01, 0x00, 0x04, 0x01, 0x00, 0x04, 0x01, 0x00, 0x00, 0x00, 0x7B, 0xEA,
       0x2C},
      {0xFD, 0x04, 0x01, 0x01, 0x01, 0x04, 0x01, 0x00, 0x04, 0x01, 0x00, 0x00, 0x00, 0x7B, 0xCD,
       0x00},
      {0xFD, 0x04, 0x01, 0x01, 0x02, 0x04, 0x01, 0x00, 0x04, 0x01, 0x00, 0x00, 0x00, 0x7B, 0xA4,
       0x74}};
  EXPECT_EQ(d.locked_coverage(), protocol::CrcCoverage::kAuto);
  for (const auto& f : frames) d.feed_frame(f.data(), f.size());
  EXPECT_EQ(d.stats().parser.frames_good, 3u);
  EXPECT_EQ(d.locked_coverage(), protocol::CrcCoverage::kWholeFrame);
  EXPECT_EQ(d.stats().locked_coverage, protocol::CrcCoverage::kWholeFrame);
}

}  // namespace
}  // namespace k40t::session
