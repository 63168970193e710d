// The streaming PSDK parser: resync on garbage, every chunk split, bad frames hiding good ones,
// the length/version/CRC16/CRC32 checks and their counters.
#include <gtest/gtest.h>

#include <vector>

#include "k40t_driver/psdk/frame.h"
#include "k40t_driver/psdk/parser.h"
#include "psdk_test_support.h"

namespace k40t::psdk {
namespace {

using testing::Bytes;
using testing::kGetVersion;
using testing::kGetVersionAck;

Bytes frame_with(uint16_t sequence, const Bytes& data,
                 CommandKey key = key_of(CommandSet::kCamera, 0x07)) {
  return testing::command_frame(key, sequence, data);
}

struct Collected {
  std::vector<Bytes> frames;
  std::vector<FrameHeader> headers;
};

Collected parse(FrameParser& parser, const Bytes& stream, size_t chunk = 0) {
  Collected out;
  const auto on_frame = [&](const FrameView& f) {
    out.frames.emplace_back(f.bytes, f.bytes + f.size);
    out.headers.push_back(f.header);
  };
  if (chunk == 0) chunk = stream.size();
  for (size_t i = 0; i < stream.size(); i += chunk) {
    parser.feed(stream.data() + i, std::min(chunk, stream.size() - i), on_frame);
  }
  return out;
}

Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const Bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// Parses `stream` in one chunk, expects `expected` to be the only frame found in it, and returns
// the parser's counters.
ParserStats stats_after_the_only_frame(const Bytes& stream, const Bytes& expected) {
  FrameParser parser;
  const Collected c = parse(parser, stream);
  EXPECT_EQ(c.frames, std::vector<Bytes>{expected});
  return parser.stats();
}

TEST(PsdkParser, ParsesTheDocumentVectors) {
  FrameParser parser;
  const Collected c = parse(parser, concat({kGetVersion, kGetVersionAck}));
  ASSERT_EQ(c.frames.size(), 2u);
  EXPECT_EQ(c.frames[0], kGetVersion);
  EXPECT_EQ(c.frames[1], kGetVersionAck);
  EXPECT_EQ(c.headers[1].packet_type, PacketType::kAck);
  EXPECT_EQ(parser.stats().frames_good, 2u);
  EXPECT_EQ(parser.stats().bytes_discarded, 0u);
}

TEST(PsdkParser, DataPointsAtDataAndPaddingIsReported) {
  FrameParser parser;
  size_t data_size = 0;
  uint8_t first = 0;
  parser.feed(kGetVersionAck.data(), kGetVersionAck.size(), [&](const FrameView& f) {
    data_size = f.data_size;
    first = f.data[3];
  });
  EXPECT_EQ(data_size, 5u);
  EXPECT_EQ(first, 0x03);
}

TEST(PsdkParser, SkipsGarbageIncludingFalseSofs) {
  const Bytes garbage = {0x00, 0xaa, 0xaa, 0x13, 0xaa, 0x10, 0x00, 0x55, 0xff, 0xaa};
  FrameParser parser;
  const Collected c =
      parse(parser, concat({garbage, kGetVersion, garbage, kGetVersionAck, garbage}));
  ASSERT_EQ(c.frames.size(), 2u);
  EXPECT_EQ(c.frames[0], kGetVersion);
  EXPECT_EQ(c.frames[1], kGetVersionAck);
  // In the trailing garbage, "aa 10 00 55 ff aa" is a plausible header (length 16, version 0)
  // still waiting for its CRC16: those 6 bytes are kept, the 4 before them are discarded.
  EXPECT_EQ(parser.stats().bytes_discarded, 2 * garbage.size() + 4);
}

TEST(PsdkParser, EverySplitPointGivesTheSameFrames) {
  const Bytes stream =
      concat({Bytes{0x01, 0xaa}, kGetVersion, frame_with(7, Bytes(200, 0xaa)), kGetVersionAck});
  FrameParser whole;
  const Collected expected = parse(whole, stream);
  ASSERT_EQ(expected.frames.size(), 3u);
  for (size_t split = 1; split < stream.size(); ++split) {
    FrameParser parser;
    Collected c;
    const auto on_frame = [&](const FrameView& f) {
      c.frames.emplace_back(f.bytes, f.bytes + f.size);
    };
    parser.feed(stream.data(), split, on_frame);
    parser.feed(stream.data() + split, stream.size() - split, on_frame);
    EXPECT_EQ(c.frames, expected.frames) << "split at " << split;
  }
  for (size_t chunk : {size_t{1}, size_t{2}, size_t{3}, size_t{7}, size_t{64}}) {
    FrameParser parser;
    EXPECT_EQ(parse(parser, stream, chunk).frames, expected.frames) << "chunks of " << chunk;
  }
}

TEST(PsdkParser, BadFrameHidingAGoodOneLosesOnlyTheBadOne) {
  // A frame whose length was corrupted upwards (still a valid header CRC is impossible, so the
  // corruption is in DATA here: the CRC32 fails) swallows the next frame; the parser must find it.
  Bytes bad = frame_with(1, Bytes(40, 0x33));
  bad[20] ^= 0x01;  // break the CRC32
  EXPECT_EQ(stats_after_the_only_frame(concat({bad, kGetVersion}), kGetVersion).frame_crc_errors,
            1u);
}

TEST(PsdkParser, FrameInsideTheDataOfABrokenFrameIsFound) {
  // The good frame is carried inside another frame's DATA, whose CRC32 is then broken.
  Bytes outer = frame_with(2, concat({Bytes{0x00, 0x01}, kGetVersionAck, Bytes{0x02}}));
  outer[outer.size() - 1] ^= 0xFF;
  EXPECT_EQ(stats_after_the_only_frame(outer, kGetVersionAck).frame_crc_errors, 1u);
}

TEST(PsdkParser, HeaderCrcErrorDoesNotWaitForTheClaimedLength) {
  // A false SOF claiming 272 bytes with a bad CRC16, right before a good frame: the good frame
  // comes out at once, without 272 bytes having to arrive first.
  const Bytes fake = {0xaa, 0x10, 0x01, 0x00, 0x00, 0x00, 0x01, 0x01, 0x00, 0x00, 0x12, 0x34};
  EXPECT_EQ(stats_after_the_only_frame(concat({fake, kGetVersion}), kGetVersion).header_crc_errors,
            1u);
}

TEST(PsdkParser, RejectsLengthsOutOfRangeAndNonZeroVersion) {
  FrameParser parser;
  const Bytes short_length = {0xaa, 0x0f, 0x00};  // 15 < 16
  const Bytes long_length = {0xaa, 0x11, 0x01};   // 273 > 272
  const Bytes version_one = {0xaa, 0x10, 0x04};   // version bits = 1
  const Collected c = parse(parser, concat({short_length, long_length, version_one, kGetVersion}));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(parser.stats().length_errors, 2u);
  EXPECT_EQ(parser.stats().version_errors, 1u);
}

TEST(PsdkParser, AcceptsTheLongestFrame) {
  const Bytes big = frame_with(3, Bytes(kMaxDataSize, 0x5A));
  ASSERT_EQ(big.size(), kMaxFrameSize);
  FrameParser parser;
  const Collected c = parse(parser, concat({big, big}), 100);
  EXPECT_EQ(c.frames.size(), 2u);
}

TEST(PsdkParser, CountsGapsInTheOtherSidesCommandSequence) {
  FrameParser parser;
  parse(parser,
        concat({frame_with(10, {}), frame_with(11, {}), frame_with(14, {}), kGetVersionAck}));
  EXPECT_EQ(parser.stats().sequence_gaps, 1u);
  EXPECT_EQ(parser.stats().commands_lost, 2u);
  // ACKs carry our own sequence numbers and do not count.
  parse(parser, frame_with(15, {}));
  EXPECT_EQ(parser.stats().sequence_gaps, 1u);
}

TEST(PsdkParser, ResetDropsAPartialFrame) {
  FrameParser parser;
  parser.feed(kGetVersion.data(), 8, [](const FrameView&) { FAIL() << "no frame expected"; });
  parser.reset();
  const Collected c = parse(parser, kGetVersionAck);
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0], kGetVersionAck);
}

TEST(PsdkParser, SurvivesLongRandomNoise) {
  Bytes noise(20000);
  uint32_t x = 12345;
  for (uint8_t& b : noise) {
    x = x * 1103515245u + 12345u;
    b = static_cast<uint8_t>(x >> 16);
    if ((x & 0x700) == 0) b = kSof;
  }
  FrameParser parser;
  const Collected c = parse(parser, concat({noise, kGetVersion, noise, kGetVersionAck}), 333);
  ASSERT_GE(c.frames.size(), 2u);
  EXPECT_EQ(c.frames[c.frames.size() - 1], kGetVersionAck);
  EXPECT_EQ(parser.stats().bytes_received,
            2 * noise.size() + kGetVersion.size() + kGetVersionAck.size());
}

}  // namespace
}  // namespace k40t::psdk
