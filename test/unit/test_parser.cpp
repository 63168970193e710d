// The streaming frame parser (src/protocol/parser.cpp; frame layout of document section 2.1).
// Streams are built from the hand-written golden frames and from frames made with encode_frame
// (itself tested against hand-written bytes in test_frame.cpp).
#include <gtest/gtest.h>

#include <numeric>
#include <random>
#include <vector>

#include "k40t_driver/protocol/crc.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/parser.h"
#include "parser_test_support.h"

namespace k40t::protocol {
namespace {

using namespace parser_testing;

TEST(Parser, FindsEveryGoldenFrameInOneChunk) {
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  expect_same_frames(feed(parser, golden_stream()), golden_frames());
  EXPECT_EQ(parser.stats().frames_good, golden_frames().size());
  EXPECT_EQ(parser.stats().bytes_discarded, 0u);
  EXPECT_EQ(parser.stats().checksum_errors, 0u);
  EXPECT_EQ(parser.stats().unknown_ids, 0u);
  EXPECT_EQ(parser.buffered_bytes(), 0u);
}

TEST(Parser, StreamSplitAtEveryByteBoundary) {
  const Bytes stream = golden_stream();
  const std::vector<Bytes> expected = golden_frames();
  for (size_t split = 0; split <= stream.size(); ++split) {
    FrameParser parser(CrcCoverage::kHeaderExcluded);
    const Collected found =
        feed(parser, stream, {split == 0 ? stream.size() : split, stream.size()});
    SCOPED_TRACE("split at " + std::to_string(split));
    expect_same_frames(found, expected);
  }
}

TEST(Parser, ByteAtATimeAndOddChunks) {
  const Bytes stream = golden_stream();
  for (const std::vector<size_t>& chunks : {std::vector<size_t>{1}, {2, 3}, {7}, {13, 1, 255}}) {
    FrameParser parser(CrcCoverage::kHeaderExcluded);
    expect_same_frames(feed(parser, stream, chunks), golden_frames());
  }
}

TEST(Parser, ChunksLargerThanItsBuffer) {
  Bytes stream;
  std::vector<Bytes> expected;
  for (int i = 0; i < 600; ++i) {  // 600 x 32 bytes = 19200 bytes, several buffers' worth
    expected.push_back(attitude_frame(static_cast<uint8_t>(i)));
    append(stream, expected.back());
  }
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  expect_same_frames(feed(parser, stream), expected);
  EXPECT_EQ(parser.stats().sequence_gaps, 0u);
  FrameParser chunked(CrcCoverage::kHeaderExcluded);
  expect_same_frames(feed(chunked, stream, {5000, 3, 4093}), expected);
}

TEST(Parser, GarbageBetweenFrames) {
  std::mt19937 rng(42);
  Bytes stream;
  std::vector<Bytes> expected;
  size_t garbage = 0;
  for (int i = 0; i < 200; ++i) {
    const size_t n = rng() % 40;
    for (size_t k = 0; k < n; ++k) {
      // Plenty of false STX bytes among the garbage.
      stream.push_back(rng() % 4 == 0 ? kStx : static_cast<uint8_t>(rng()));
    }
    garbage += n;
    expected.push_back(attitude_frame(static_cast<uint8_t>(i)));
    append(stream, expected.back());
  }
  // An idle line after the last frame: a false STX just before it may claim up to 243 bytes, and
  // the frame inside that claim is only found once the claim is complete (see the next test).
  append(stream, Bytes(kMaxFrameSize, 0x00));
  garbage += kMaxFrameSize;
  for (const std::vector<size_t>& chunks : {std::vector<size_t>{stream.size()}, {1}, {17}}) {
    FrameParser parser(CrcCoverage::kHeaderExcluded);
    const Collected found = feed(parser, stream, chunks);
    expect_same_frames(found, expected);
    EXPECT_EQ(parser.stats().bytes_discarded, garbage);
    expect_bytes_accounted(parser, found);
  }
}

TEST(Parser, FalseStxWhoseLengthSpansTheNextFrame) {
  // FD 40 ...: a plausible header claiming 64 payload bytes; the real frame starts 3 bytes later.
  Bytes stream = {kStx, 0x40, 0x01};
  const Bytes good = attitude_frame(9);
  append(stream, good);
  append(stream, Bytes(60, 0x00));  // enough bytes for the false candidate to be complete
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  const Collected found = feed(parser, stream);
  ASSERT_EQ(found.frames.size(), 1u);
  EXPECT_EQ(found.frames[0], good);
  EXPECT_GE(parser.stats().checksum_errors, 1u);
  EXPECT_EQ(parser.stats().bytes_discarded, stream.size() - good.size());
}

TEST(Parser, AFrameInsideAnIncompleteFalseStxClaimWaitsForTheClaim) {
  // FD C8: a false STX claiming 200 payload bytes. The good frame behind it is not delivered
  // until the claim's 212 bytes are in (so that a real frame's payload is never mistaken for
  // frames); on a live link the pod's periodic reports complete the claim within a fraction of a
  // second.
  Bytes stream = {kStx, 200};
  const Bytes good = attitude_frame(1);
  append(stream, good);
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  EXPECT_TRUE(feed(parser, stream).frames.empty());
  EXPECT_EQ(parser.buffered_bytes(), stream.size());
  const Collected later = feed(parser, Bytes(212 - stream.size(), 0x00));
  ASSERT_EQ(later.frames.size(), 1u);
  EXPECT_EQ(later.frames[0], good);
}

TEST(Parser, TruncatedFramesDoNotHideTheNextOne) {
  const Bytes a = attitude_frame(1);
  const Bytes b = attitude_frame(2);
  Bytes stream(a.begin(), a.begin() + 15);  // a, cut after 15 of its 32 bytes
  append(stream, b);
  append(stream, Bytes(a.begin(), a.begin() + 5));  // and another cut one at the very end
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  const Collected found = feed(parser, stream);
  ASSERT_EQ(found.frames.size(), 1u);
  EXPECT_EQ(found.frames[0], b);
  EXPECT_EQ(parser.buffered_bytes(), 5u) << "the last, incomplete frame waits for more bytes";
  expect_bytes_accounted(parser, found);

  parser.reset();  // e.g. a reconnect: the partial frame is dropped and counted
  EXPECT_EQ(parser.buffered_bytes(), 0u);
  EXPECT_EQ(parser.stats().bytes_discarded, 15u + 5u);
  expect_bytes_accounted(parser, found);
  EXPECT_EQ(feed(parser, a).frames.size(), 1u);
}

TEST(Parser, MaximumLengthFrame) {
  Bytes payload(kMaxPayloadSize);
  std::iota(payload.begin(), payload.end(), 0);  // includes 0xFD bytes inside the payload
  const Bytes frame = make_frame(0x000100, 0, payload, kCameraAddress);
  ASSERT_EQ(frame.size(), 255u);
  ASSERT_EQ(frame[1], 243);
  for (size_t chunk : {size_t{255}, size_t{1}, size_t{254}}) {
    FrameParser parser(CrcCoverage::kHeaderExcluded);
    const Collected found = feed(parser, frame, {chunk});
    ASSERT_EQ(found.frames.size(), 1u);
    EXPECT_EQ(found.frames[0], frame);
  }
}

TEST(Parser, LengthOver243IsNotAFrame) {
  // FD F4: LEN 244, one more than section 2.1 allows. Build it by hand with a valid checksum over
  // 244 bytes, so only the length rule can reject it.
  Bytes bad = {kStx, 244, 0x01, 0x01, 0x00, 0x03, 0x01, 0x02, 0x00, 0x00};
  bad.resize(kHeaderSize + 244, 0x11);
  const uint16_t crc = crc16(bad.data() + 1, bad.size() - 1);
  bad.push_back(static_cast<uint8_t>(crc));
  bad.push_back(static_cast<uint8_t>(crc >> 8));
  const Bytes good = attitude_frame(3);
  Bytes stream = bad;
  append(stream, good);
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  const Collected found = feed(parser, stream);
  ASSERT_EQ(found.frames.size(), 1u);
  EXPECT_EQ(found.frames[0], good);
  EXPECT_EQ(parser.stats().length_errors, 1u);
  EXPECT_EQ(parser.stats().bytes_discarded, bad.size());
  for (int len = 244; len <= 255; ++len) {
    if (len == kStx) continue;  // FD FD FD 14...: two false STX in a row, two length errors
    FrameParser p(CrcCoverage::kHeaderExcluded);
    Bytes s = {kStx, static_cast<uint8_t>(len)};
    append(s, good);
    EXPECT_EQ(feed(p, s).frames.size(), 1u) << "LEN " << len;
    EXPECT_EQ(p.stats().length_errors, 1u);
  }
}

TEST(Parser, BadChecksumFrameWhosePayloadHoldsAGoodFrame) {
  const Bytes inner = attitude_frame(7);
  Bytes payload(kMaxPayloadSize, 0x22);
  std::copy(inner.begin(), inner.end(), payload.begin() + 100);
  Bytes outer = make_frame(0x000100, 0, payload, kCameraAddress);
  outer[outer.size() - 1] ^= 0x01;  // break the outer frame's checksum
  for (size_t chunk : {outer.size(), size_t{1}, size_t{64}}) {
    FrameParser parser(CrcCoverage::kHeaderExcluded);
    const Collected found = feed(parser, outer, {chunk});
    ASSERT_EQ(found.frames.size(), 1u) << "chunk " << chunk;
    EXPECT_EQ(found.frames[0], inner);
    EXPECT_GE(parser.stats().checksum_errors, 1u);
    EXPECT_EQ(parser.stats().bytes_discarded, outer.size() - inner.size());
  }
}

TEST(Parser, GoodFrameInsideAGoodFrameIsPayload) {
  // The other side of the rescan rule: a valid outer frame is taken whole, and its payload is
  // not searched for frames.
  const Bytes inner = attitude_frame(7);
  Bytes payload(100, 0x22);
  std::copy(inner.begin(), inner.end(), payload.begin() + 10);
  const Bytes outer = make_frame(0x000100, 0, payload, kCameraAddress);
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  const Collected found = feed(parser, outer);
  ASSERT_EQ(found.frames.size(), 1u);
  EXPECT_EQ(found.frames[0], outer);
}

}  // namespace
}  // namespace k40t::protocol
