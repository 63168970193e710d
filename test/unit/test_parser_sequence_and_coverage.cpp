// The streaming frame parser (src/protocol/parser.cpp; frame layout of document section 2.1) on
// streams of frames made with encode_frame: sequence gaps and repeats per source, the CRC coverage
// it locks onto or is configured with, unknown ids, and byte accounting on a corrupted stream.
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

TEST(Parser, SequenceGapsPerSourceAcrossTheWrap) {
  const Address gimbal = kGimbalAddress;
  const Address camera = kCameraAddress;
  Bytes stream;
  // Gimbal: 253 254 255 0 1 (no gap across the wrap), then 4 (2 and 3 lost).
  for (int s : {253, 254, 255, 0, 1, 4})
    append(stream, attitude_frame(static_cast<uint8_t>(s), gimbal));
  // Camera, interleaved after them: its own counter, 10 11 12 — no gap even though the gimbal's
  // numbers are elsewhere.
  for (int s : {10, 11, 12}) append(stream, attitude_frame(static_cast<uint8_t>(s), camera));
  // Gimbal again: 5 (continues from 4), then 254 -> wraps past 255 and 0 to 2: gap.
  for (int s : {5, 254}) append(stream, attitude_frame(static_cast<uint8_t>(s), gimbal));
  append(stream, attitude_frame(2, gimbal));  // after 254: 255, 0, 1 lost

  FrameParser parser(CrcCoverage::kHeaderExcluded);
  feed(parser, stream);
  EXPECT_EQ(parser.stats().frames_good, 12u);
  // Gaps: 1 -> 4 (lost 2), 5 -> 254 (lost 248), 254 -> 2 (lost 3).
  EXPECT_EQ(parser.stats().sequence_gaps, 3u);
  EXPECT_EQ(parser.stats().frames_lost, 2u + 248u + 3u);

  parser.reset();  // forgets the history: the next frame of each source starts afresh
  feed(parser, attitude_frame(100, gimbal));
  EXPECT_EQ(parser.stats().sequence_gaps, 3u);
}

TEST(Parser, ARepeatedSequenceNumberIsADuplicateNotAGap) {
  // Gimbal 7, 7 (the same frame twice), 8: one repeat, no gap, nothing lost.
  Bytes stream;
  for (int s : {7, 7, 8}) append(stream, attitude_frame(static_cast<uint8_t>(s), kGimbalAddress));
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  feed(parser, stream);
  EXPECT_EQ(parser.stats().frames_good, 3u);
  EXPECT_EQ(parser.stats().frames_repeated, 1u);
  EXPECT_EQ(parser.stats().sequence_gaps, 0u);
  EXPECT_EQ(parser.stats().frames_lost, 0u);
}

TEST(Parser, AutoCoverageLocksOntoWholeFrameChecksums) {
  FrameParser parser(CrcCoverage::kAuto);
  EXPECT_EQ(parser.coverage(), CrcCoverage::kAuto);
  Bytes stream;
  for (uint8_t s = 0; s < FrameParser::kLockFrames; ++s) {
    append(stream, attitude_frame(s, kGimbalAddress, CrcCoverage::kWholeFrame));
  }
  const Collected found = feed(parser, stream);
  ASSERT_EQ(found.frames.size(), 3u);
  for (CrcCoverage c : found.coverages) EXPECT_EQ(c, CrcCoverage::kWholeFrame);
  EXPECT_EQ(parser.coverage(), CrcCoverage::kWholeFrame);
  EXPECT_EQ(parser.configured_coverage(), CrcCoverage::kAuto);

  // Locked: a header_excluded frame no longer counts.
  const Collected after =
      feed(parser, attitude_frame(3, kGimbalAddress, CrcCoverage::kHeaderExcluded));
  EXPECT_TRUE(after.frames.empty());
  EXPECT_EQ(parser.stats().checksum_errors, 1u);
  EXPECT_EQ(feed(parser, attitude_frame(4, kGimbalAddress, CrcCoverage::kWholeFrame)).frames.size(),
            1u);
}

TEST(Parser, AutoCoverageNeedsConsecutiveAgreement) {
  FrameParser parser(CrcCoverage::kAuto);
  Bytes stream;
  // Before locking both coverages are accepted; the lock needs kLockFrames in a row.
  append(stream, attitude_frame(0, kGimbalAddress, CrcCoverage::kWholeFrame));
  append(stream, attitude_frame(1, kGimbalAddress, CrcCoverage::kWholeFrame));
  append(stream, attitude_frame(2, kGimbalAddress, CrcCoverage::kHeaderExcluded));
  append(stream, attitude_frame(3, kGimbalAddress, CrcCoverage::kHeaderExcluded));
  const Collected found = feed(parser, stream);
  ASSERT_EQ(found.frames.size(), 4u);
  EXPECT_EQ(found.coverages[0], CrcCoverage::kWholeFrame);
  EXPECT_EQ(found.coverages[3], CrcCoverage::kHeaderExcluded);
  EXPECT_EQ(parser.coverage(), CrcCoverage::kAuto);
  feed(parser, attitude_frame(4, kGimbalAddress, CrcCoverage::kHeaderExcluded));
  EXPECT_EQ(parser.coverage(), CrcCoverage::kHeaderExcluded);
}

TEST(Parser, ConfiguredCoverageRejectsTheOther) {
  FrameParser header_excluded(CrcCoverage::kHeaderExcluded);
  EXPECT_TRUE(feed(header_excluded, attitude_frame(0, kGimbalAddress, CrcCoverage::kWholeFrame))
                  .frames.empty());
  EXPECT_EQ(header_excluded.stats().checksum_errors, 1u);
  FrameParser whole(CrcCoverage::kWholeFrame);
  EXPECT_TRUE(feed(whole, attitude_frame(0)).frames.empty());
  EXPECT_EQ(feed(whole, attitude_frame(1, kGimbalAddress, CrcCoverage::kWholeFrame)).frames.size(),
            1u);
}

TEST(Parser, CountsUnknownIdsButDeliversThem) {
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  const Collected found = feed(parser, make_frame(0x0000FE, 0, {1, 2, 3}));
  EXPECT_EQ(found.frames.size(), 1u);
  EXPECT_EQ(parser.stats().unknown_ids, 1u);
}

TEST(Parser, BytesDiscardedAccountingOnARandomlyCorruptedStream) {
  std::mt19937 rng(5);
  Bytes stream;
  for (int i = 0; i < 500; ++i) append(stream, attitude_frame(static_cast<uint8_t>(i)));
  size_t flipped = 0;
  for (auto& b : stream) {
    if (rng() % 100 == 0) {
      b ^= static_cast<uint8_t>(1 + rng() % 255);
      ++flipped;
    }
  }
  ASSERT_GT(flipped, 0u);
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  const Collected found = feed(parser, stream, {1, 100, 37});
  expect_bytes_accounted(parser, found);
  // A flipped byte spoils at most the frame it is in.
  EXPECT_GE(found.frames.size(), 500u - flipped);
  EXPECT_LT(found.frames.size(), 500u);
  for (const Bytes& f : found.frames) EXPECT_EQ(f.size(), 32u);
}

}  // namespace
}  // namespace k40t::protocol
