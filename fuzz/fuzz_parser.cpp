// libFuzzer target: the streaming frame parser on arbitrary bytes in arbitrary chunks.
//
// Input: the stream (taken from the front) and, from the back, the checksum coverage mode and the
// chunk sizes (FuzzedDataProvider takes integers from the end, so a seed that is just frames
// still parses as those frames). Besides crashes and sanitizer reports, it aborts when:
//   - a delivered frame is malformed (no STX, size != 12 + LEN, LEN > 243);
//   - the byte accounting does not add up (received == good + discarded + buffered);
//   - chunking changes the result: the same bytes fed in one piece give other frames.
// Every good frame is also decoded through the catalogue, as the driver would.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/parser.h"
#include "null_sink.h"

namespace {

using k40t::protocol::CodecOptions;
using k40t::protocol::CrcCoverage;
using k40t::protocol::FrameParser;
using k40t::protocol::FrameView;

void check(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "fuzz_parser: invariant broken: %s\n", what);
    std::abort();
  }
}

struct Run {
  std::vector<std::vector<uint8_t>> frames;
  uint64_t good_bytes = 0;
};

void on_frame(const FrameView& f, Run& run) {
  check(f.size >= k40t::protocol::kFrameOverhead && f.size <= k40t::protocol::kMaxFrameSize,
        "frame size within 12..255");
  check(f.bytes[0] == k40t::protocol::kStx, "frame starts with STX");
  check(f.payload_size == f.bytes[1] && f.size == k40t::protocol::kFrameOverhead + f.payload_size,
        "size == 12 + LEN");
  check(f.payload == f.bytes + k40t::protocol::kHeaderSize, "payload follows the header");
  run.frames.emplace_back(f.bytes, f.bytes + f.size);
  run.good_bytes += f.size;
  if (const auto* info = k40t::protocol::find_message(f.header.message_id)) {
    k40t::fuzz::NullSink sink;
    info->describe(f.payload, f.payload_size, CodecOptions{}, sink);  // may refuse, must not crash
  }
}

void check_accounting(const FrameParser& parser, const Run& run) {
  const auto& s = parser.stats();
  check(s.bytes_received == run.good_bytes + s.bytes_discarded + parser.buffered_bytes(),
        "bytes_received == good + discarded + buffered");
  check(s.frames_good == run.frames.size(), "frames_good counts the callbacks");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider input(data, size);
  const CrcCoverage coverage = static_cast<CrcCoverage>(input.ConsumeIntegralInRange<int>(0, 2));
  const size_t chunk_budget = input.ConsumeIntegralInRange<size_t>(0, 16);
  std::vector<size_t> chunks;
  for (size_t i = 0; i < chunk_budget; ++i)
    chunks.push_back(input.ConsumeIntegralInRange<size_t>(1, 600));
  const std::vector<uint8_t> stream = input.ConsumeRemainingBytes<uint8_t>();

  FrameParser chunked(coverage);
  Run a;
  size_t pos = 0;
  for (size_t i = 0; pos < stream.size(); ++i) {
    const size_t n =
        chunks.empty() ? stream.size() : std::min(chunks[i % chunks.size()], stream.size() - pos);
    chunked.feed(stream.data() + pos, n, [&](const FrameView& f) { on_frame(f, a); });
    pos += n;
    check_accounting(chunked, a);
  }

  FrameParser whole(coverage);
  Run b;
  whole.feed(stream.data(), stream.size(), [&](const FrameView& f) { on_frame(f, b); });
  check_accounting(whole, b);
  check(a.frames == b.frames, "chunking does not change the frames found");
  check(chunked.stats().bytes_discarded == whole.stats().bytes_discarded,
        "nor the bytes discarded");

  chunked.reset();
  check(chunked.buffered_bytes() == 0, "reset empties the buffer");
  check_accounting(chunked, a);
  return 0;
}
