// Parser and encoder throughput (Google Benchmark).
//
// The input is what a serial link from the pod carries: the periodic reports at their documented
// rates (per second: gimbal attitude 10, thermal 5, visible 5, gimbal status 2, camera status 1,
// upgrade/repair 1, record status 1, periodic laser range 1) plus a few ACKs, interleaved as they
// would be in time, for 600 simulated seconds, with ~1% of the bytes corrupted.
//
// BM_ParseMixedFrameParser runs the project's FrameParser (memchr STX hunt, table CRC, rescan
// after a bad candidate). BM_ParseMixedBaseline runs, on the same bytes, the plain parser most
// embedded code has: a byte-at-a-time state machine with the document's crc_accumulate
// (crc_accumulate_reference), which restarts after a bad frame without rescanning it.
// scripts/bench.sh prints the FrameParser/Baseline ratio. Figures: bytes_per_second (MB/s),
// frames/s, and frames found per pass (the rescan finds frames the baseline loses).
#include <benchmark/benchmark.h>

#include <array>
#include <functional>
#include <random>
#include <vector>

#include "k40t_driver/protocol/crc.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/parser.h"

namespace {

using namespace k40t::protocol;  // frames, their parser and CRC, addresses

// ---- the input ------------------------------------------------------------------------------
struct Traffic {
  MessageId id;
  size_t payload_size;
  int per_second;
  Address source;
};
// Payload sizes from docs/protocol/decisions.md#periodic-reports; ACKs from section 3.3
// and 3.2.5.1.
constexpr Traffic kTraffic[] = {
    {0x000002, 20, 10, kGimbalAddress},  // gimbal attitude
    {0x000004, 34, 5, kCameraAddress},   // thermal status
    {0x000005, 15, 5, kCameraAddress},   // visible status
    {0x000001, 7, 2, kGimbalAddress},    // gimbal status
    {0x000003, 16, 1, kCameraAddress},   // camera system status
    {0x000008, 3, 1, kCameraAddress},    // upgrade / repair
    {0x020303, 7, 1, kCameraAddress},    // record status
    {0x020406, 4, 1, kCameraAddress},    // periodic laser range
    {0x010012, 2, 1, kGimbalAddress},    // ACK of a gimbal angle command
    {0x010400, 4, 1, kCameraAddress},    // ACK of single ranging
};

struct Stream {
  std::vector<uint8_t> bytes;
  size_t frames = 0;
};

Stream make_stream(int seconds, double corrupt_fraction) {
  std::mt19937 rng(2024);
  Stream s;
  std::array<uint8_t, 256> sequence{};  // per source system
  for (int second = 0; second < seconds; ++second) {
    // Slot the second into 10 ticks of 100 ms; each message is sent on its ticks.
    for (int tick = 0; tick < 10; ++tick) {
      for (const Traffic& t : kTraffic) {
        if (tick % (10 / t.per_second) != 0) continue;
        std::vector<uint8_t> payload(t.payload_size);
        for (auto& b : payload) b = static_cast<uint8_t>(rng());
        FrameHeader h;
        h.destination = kHostAddress;
        h.source = t.source;
        h.sequence = sequence[t.source.system]++;
        h.message_id = t.id;
        auto frame = encode_frame(h, payload.data(), payload.size(), CrcCoverage::kHeaderExcluded);
        s.bytes.insert(s.bytes.end(), frame->data(), frame->data() + frame->size());
        ++s.frames;
      }
    }
  }
  std::uniform_real_distribution<double> coin(0, 1);
  for (auto& b : s.bytes) {
    if (coin(rng) < corrupt_fraction) b ^= static_cast<uint8_t>(1 + rng() % 255);
  }
  return s;
}

const Stream& mixed_stream() {
  static const Stream s = make_stream(600, 0.01);
  return s;
}

// ---- the baseline ---------------------------------------------------------------------------
// A byte-at-a-time state machine with the document's CRC routine, header_excluded coverage.
class BaselineParser {
 public:
  using Callback = std::function<void(const uint8_t* frame, size_t size)>;

  void feed(const uint8_t* data, size_t size, const Callback& on_frame) {
    for (size_t i = 0; i < size; ++i) step(data[i], on_frame);
  }

 private:
  enum class State { kStx, kLen, kHeader, kPayload, kCrcLow, kCrcHigh };

  void step(uint8_t b, const Callback& on_frame) {
    switch (state_) {
      case State::kStx:
        if (b == kStx) {
          frame_[0] = b;
          size_ = 1;
          crc_ = kCrcInit;
          state_ = State::kLen;
        }
        return;
      case State::kLen:
        if (b > kMaxPayloadSize) {
          state_ = State::kStx;
          return;
        }
        payload_size_ = b;
        push(b);
        state_ = State::kHeader;
        return;
      case State::kHeader:
        push(b);
        if (size_ == kHeaderSize) state_ = payload_size_ > 0 ? State::kPayload : State::kCrcLow;
        return;
      case State::kPayload:
        push(b);
        if (size_ == kHeaderSize + payload_size_) state_ = State::kCrcLow;
        return;
      case State::kCrcLow:
        frame_[size_++] = b;
        state_ = State::kCrcHigh;
        return;
      case State::kCrcHigh:
        frame_[size_++] = b;
        state_ = State::kStx;
        if ((frame_[size_ - 2] | b << 8) == crc_) on_frame(frame_.data(), size_);
        return;
    }
  }
  void push(uint8_t b) {
    frame_[size_++] = b;
    crc_accumulate_reference(b, &crc_);
  }

  State state_ = State::kStx;
  std::array<uint8_t, kMaxFrameSize> frame_{};
  size_t size_ = 0;
  size_t payload_size_ = 0;
  uint16_t crc_ = 0;
};

// ---- benchmarks -----------------------------------------------------------------------------
void report(benchmark::State& state, size_t stream_bytes, size_t frames_found_total,
            size_t passes) {
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * stream_bytes));
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(frames_found_total), benchmark::Counter::kIsRate);
  state.counters["found/pass"] =
      static_cast<double>(frames_found_total) / static_cast<double>(passes);
  state.counters["sent/pass"] = static_cast<double>(mixed_stream().frames);
}

// The chunk sizes the bytes arrive in (a serial read returns what has arrived): a byte at a time,
// the few bytes a fast poll returns, a USB-serial packet, and a large buffered read.
void read_sizes(benchmark::internal::Benchmark* b) {
  for (int64_t size : {1, 16, 64, 4096}) b->Arg(size);
  b->Unit(benchmark::kMillisecond);
}

// Arg: the chunk size.
void BM_ParseMixedFrameParser(benchmark::State& state) {
  const Stream& s = mixed_stream();
  const size_t chunk = static_cast<size_t>(state.range(0));
  size_t found = 0;
  const FrameParser::FrameCallback on_frame = [&](const FrameView& f) {
    benchmark::DoNotOptimize(f.payload);
    ++found;
  };
  for (auto _ : state) {
    FrameParser parser(CrcCoverage::kAuto);
    for (size_t pos = 0; pos < s.bytes.size(); pos += chunk) {
      parser.feed(s.bytes.data() + pos, std::min(chunk, s.bytes.size() - pos), on_frame);
    }
  }
  report(state, s.bytes.size(), found, state.iterations());
}
BENCHMARK(BM_ParseMixedFrameParser)->Apply(read_sizes);

void BM_ParseMixedBaseline(benchmark::State& state) {
  const Stream& s = mixed_stream();
  const size_t chunk = static_cast<size_t>(state.range(0));
  size_t found = 0;
  const BaselineParser::Callback on_frame = [&](const uint8_t* frame, size_t) {
    benchmark::DoNotOptimize(frame);
    ++found;
  };
  for (auto _ : state) {
    BaselineParser parser;
    for (size_t pos = 0; pos < s.bytes.size(); pos += chunk) {
      parser.feed(s.bytes.data() + pos, std::min(chunk, s.bytes.size() - pos), on_frame);
    }
  }
  report(state, s.bytes.size(), found, state.iterations());
}
BENCHMARK(BM_ParseMixedBaseline)->Apply(read_sizes);

// encode_payload + encode_frame of the most frequent message, the 10 Hz attitude report (the
// simulator's hot path) and of a request the host sends.
template <class T>
void encode_loop(benchmark::State& state, const T& message, Address destination) {
  FrameHeader h;
  h.destination = destination;
  h.source = kHostAddress;
  h.message_id = T::kId;
  size_t bytes = 0;
  for (auto _ : state) {
    auto payload = encode_payload(message);
    auto frame = encode_frame(h, payload->data(), payload->size, CrcCoverage::kHeaderExcluded);
    benchmark::DoNotOptimize(frame->data());
    bytes += frame->size();
    ++h.sequence;
  }
  state.SetBytesProcessed(static_cast<int64_t>(bytes));
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_EncodeGimbalAttitude(benchmark::State& state) {
  GimbalAttitude m;
  m.joint_yaw_deg = 12.34;
  m.pitch_deg = -45;
  m.yaw_rate_deg_s = 10.5;
  encode_loop(state, m, kHostAddress);
}
BENCHMARK(BM_EncodeGimbalAttitude);

void BM_EncodeGimbalAngleRequest(benchmark::State& state) {
  GimbalAngleRequest m;
  m.pitch_deg = -45.5;
  m.yaw_deg = 120.25;
  encode_loop(state, m, kGimbalAddress);
}
BENCHMARK(BM_EncodeGimbalAngleRequest);

}  // namespace

BENCHMARK_MAIN();
