// The streaming frame parser (src/protocol/parser.cpp; frame layout of document section 2.1).
// Streams are built from the hand-written golden frames and from frames made with encode_frame
// (itself tested against hand-written bytes in test_frame.cpp).
#include <gtest/gtest.h>

#include <numeric>
#include <random>
#include <vector>

#include "golden_checks.h"
#include "k40t_driver/protocol/crc.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

Bytes make_frame(MessageId id, uint8_t sequence, const Bytes& payload,
                 Address source = kGimbalAddress,
                 CrcCoverage coverage = CrcCoverage::kHeaderExcluded) {
  FrameHeader h;
  h.destination = kHostAddress;
  h.sequence = sequence;
  h.source = source;
  h.message_id = id;
  auto frame = encode_frame(h, payload.data(), payload.size(), coverage);
  EXPECT_TRUE(frame) << frame.error();
  return frame ? Bytes(frame->data(), frame->data() + frame->size()) : Bytes{};
}

// The gimbal attitude report (0x000002) with 20 payload bytes of a recognisable pattern.
Bytes attitude_frame(uint8_t sequence, Address source = kGimbalAddress,
                     CrcCoverage coverage = CrcCoverage::kHeaderExcluded) {
  Bytes payload(20);
  std::iota(payload.begin(), payload.end(), sequence);
  return make_frame(0x000002, sequence, payload, source, coverage);
}

Bytes golden_stream() {
  Bytes all;
  for (const auto& g : testing::load_golden("gimbal_laser_sbus.txt"))
    all.insert(all.end(), g.bytes.begin(), g.bytes.end());
  return all;
}

std::vector<Bytes> golden_frames() {
  std::vector<Bytes> frames;
  for (const auto& g : testing::load_golden("gimbal_laser_sbus.txt")) frames.push_back(g.bytes);
  return frames;
}

void append(Bytes& to, const Bytes& more) {
  to.insert(to.end(), more.begin(), more.end());
}

// Feeds `stream` in the given chunk sizes (cycled; none = one chunk) and returns the frames found,
// byte for byte.
struct Collected {
  std::vector<Bytes> frames;
  std::vector<CrcCoverage> coverages;
};
Collected feed(FrameParser& parser, const Bytes& stream, const std::vector<size_t>& chunks = {}) {
  Collected out;
  auto on_frame = [&](const FrameView& f) {
    out.frames.emplace_back(f.bytes, f.bytes + f.size);
    out.coverages.push_back(f.coverage);
  };
  size_t pos = 0;
  for (size_t i = 0; pos < stream.size(); ++i) {
    const size_t chunk = chunks.empty() ? stream.size() : chunks[i % chunks.size()];
    const size_t n = std::min(chunk, stream.size() - pos);
    parser.feed(stream.data() + pos, n, on_frame);
    pos += n;
  }
  return out;
}

// Compares frame lists, reporting the first difference only (not two walls of bytes).
void expect_same_frames(const Collected& found, const std::vector<Bytes>& expected) {
  EXPECT_EQ(found.frames.size(), expected.size());
  for (size_t i = 0; i < std::min(found.frames.size(), expected.size()); ++i) {
    if (found.frames[i] != expected[i]) {
      ADD_FAILURE() << "frame " << i << " differs";
      return;
    }
  }
}

// Every byte received is in a good frame, discarded, or still buffered.
void expect_bytes_accounted(const FrameParser& parser, const Collected& found) {
  size_t good = 0;
  for (const Bytes& f : found.frames) good += f.size();
  EXPECT_EQ(parser.stats().bytes_received,
            good + parser.stats().bytes_discarded + parser.buffered_bytes());
}

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
