// Helpers of the frame parser's tests (test_parser*.cpp): frames made with encode_frame, streams of
// the hand-written golden frames, feeding a stream in chunks, and checking what came out.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "golden_checks.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::protocol::parser_testing {

using Bytes = std::vector<uint8_t>;

inline Bytes make_frame(MessageId id, uint8_t sequence, const Bytes& payload,
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
inline Bytes attitude_frame(uint8_t sequence, Address source = kGimbalAddress,
                            CrcCoverage coverage = CrcCoverage::kHeaderExcluded) {
  Bytes payload(20);
  std::iota(payload.begin(), payload.end(), sequence);
  return make_frame(0x000002, sequence, payload, source, coverage);
}

inline Bytes golden_stream() {
  Bytes all;
  for (const auto& g : testing::load_golden("gimbal_laser_sbus.txt"))
    all.insert(all.end(), g.bytes.begin(), g.bytes.end());
  return all;
}

inline std::vector<Bytes> golden_frames() {
  std::vector<Bytes> frames;
  for (const auto& g : testing::load_golden("gimbal_laser_sbus.txt")) frames.push_back(g.bytes);
  return frames;
}

inline void append(Bytes& to, const Bytes& more) {
  to.insert(to.end(), more.begin(), more.end());
}

// Feeds `stream` in the given chunk sizes (cycled; none = one chunk) and returns the frames found,
// byte for byte.
struct Collected {
  std::vector<Bytes> frames;
  std::vector<CrcCoverage> coverages;
};
inline Collected feed(FrameParser& parser, const Bytes& stream,
                      const std::vector<size_t>& chunks = {}) {
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
inline void expect_same_frames(const Collected& found, const std::vector<Bytes>& expected) {
  EXPECT_EQ(found.frames.size(), expected.size());
  for (size_t i = 0; i < std::min(found.frames.size(), expected.size()); ++i) {
    if (found.frames[i] != expected[i]) {
      ADD_FAILURE() << "frame " << i << " differs";
      return;
    }
  }
}

// Every byte received is in a good frame, discarded, or still buffered.
inline void expect_bytes_accounted(const FrameParser& parser, const Collected& found) {
  size_t good = 0;
  for (const Bytes& f : found.frames) good += f.size();
  EXPECT_EQ(parser.stats().bytes_received,
            good + parser.stats().bytes_discarded + parser.buffered_bytes());
}

}  // namespace k40t::protocol::parser_testing
