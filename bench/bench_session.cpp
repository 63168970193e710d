// Session figures:
//  - BM_RequestAck: request/ACK round trip through Session::request_raw() over a pty (serial://
//    on the driver's side, pty:// on the pod's), against a minimal responder that parses each
//    request in its transport's receive callback and writes the ACK back. p50/p99/max in µs as
//    counters; each iteration is timed by hand (UseManualTime).
//  - BM_RequestAckConcurrentIds: the same with N threads each on its own message id (they
//    proceed concurrently, docs/protocol/decisions.md#a5), to show that one id's wait does not hold
//    up another's.
//  - BM_DispatcherFeed: a stream of 0x000002 attitude reports through Dispatcher::feed() with a
//    typed handler; bytes/s and heap allocations per frame (counted by replacing operator new in
//    this program only) to back the "no allocation on the steady-state receive path" claim.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <new>
#include <thread>
#include <vector>

#include "../test/unit/transport_test_support.h"  // scratch dirs, waiting
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/parser.h"
#include "k40t_driver/session/dispatcher.h"
#include "k40t_driver/session/session.h"
#include "percentiles.h"

namespace {
// Heap allocations made by this process. A benchmark-only instrument: the replaced operator new
// below must count somewhere global. It allocates with malloc, which the default operator delete
// (free) releases.
std::atomic<uint64_t> g_allocations{0};
}  // namespace

// noinline: GCC would otherwise see malloc() paired with the library's delete and warn.
__attribute__((noinline)) void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

namespace k40t::session {
namespace {

using Clock = std::chrono::steady_clock;
using transport::testing::eventually;

using bench::report_percentiles;

// The pod's side at its simplest: every request gets an OK ACK with two data bytes, written from
// the transport's receive callback (its I/O thread).
class Responder {
 public:
  explicit Responder(const std::string& url) {
    auto made = transport::make_transport(url);
    if (!made) return;
    link_ = std::move(made).value();
    link_->set_receive_callback([this](const uint8_t* data, size_t size) {
      parser_.feed(data, size, [this](const protocol::FrameView& request) { answer(request); });
    });
    ready_ = link_->open() &&
             eventually([&] { return link_->state() == transport::LinkState::kConnected; });
  }
  bool ready() const { return ready_; }

 private:
  void answer(const protocol::FrameView& request) {
    if (protocol::kind_of(request.header.message_id) != protocol::MessageKind::kRequestOrReport)
      return;
    protocol::FrameHeader ack;
    ack.destination = request.header.source;
    ack.source = request.header.destination;
    ack.sequence = sequence_++;
    ack.message_id = protocol::ack_id_of(request.header.message_id);
    const uint8_t payload[] = {0x00, 0x00, 0x00, 0x7B};  // OK, 12.3 m
    auto frame = protocol::encode_frame(ack, payload, sizeof(payload),
                                        protocol::CrcCoverage::kHeaderExcluded);
    if (frame) (void)link_->send(frame->data(), frame->size());
  }

  std::unique_ptr<transport::Transport> link_;
  protocol::FrameParser parser_{protocol::CrcCoverage::kHeaderExcluded};
  uint8_t sequence_ = 0;
  bool ready_ = false;
};

// A pod responder on a pty and a started driver session on its serial side.
struct PtySetup {
  PtySetup() : responder("pty://" + dir.file("pod")) {
    if (!responder.ready()) return;
    auto link = transport::make_transport("serial://" + dir.file("pod") + "?baud=115200");
    if (!link) return;
    SessionOptions options;
    options.ack_timeout = std::chrono::milliseconds(1000);
    options.retries = 0;
    session = std::make_unique<Session>(std::move(link).value(), options);
    ready = session->start() &&
            eventually([&] { return session->link_state() == transport::LinkState::kConnected; });
  }
  transport::testing::ScratchDir dir;
  Responder responder;
  std::unique_ptr<Session> session;
  bool ready = false;
};

void BM_RequestAck(benchmark::State& state) {
  PtySetup setup;
  if (!setup.ready) {
    state.SkipWithError("could not connect the pty pair");
    return;
  }
  const uint8_t payload[] = {0x01, 0x00};
  std::vector<double> micros;
  micros.reserve(1 << 20);
  const uint64_t allocations_before = g_allocations.load();
  for (auto _ : state) {
    const auto start = Clock::now();
    const AckResult result = setup.session->request_raw(0x000400, payload, sizeof(payload));
    const std::chrono::duration<double> took = Clock::now() - start;
    if (!result.ok()) {
      state.SkipWithError(result.message.c_str());
      return;
    }
    state.SetIterationTime(took.count());
    micros.push_back(took.count() * 1e6);
  }
  // Whole process (caller, request thread, both transports' I/O threads, the responder): the
  // request path allocates (the queued request's callback, the AckResult's payload vector).
  state.counters["allocations_per_request"] =
      static_cast<double>(g_allocations.load() - allocations_before) /
      static_cast<double>(state.iterations());
  const SessionStats stats = setup.session->stats();
  state.counters["late_acks"] = static_cast<double>(stats.late_acks);
  report_percentiles(state, std::move(micros));
}
BENCHMARK(BM_RequestAck)->UseManualTime()->Unit(benchmark::kMicrosecond);

// N threads, each requesting its own id in a loop for a fixed count; the figure is the wall time
// per request over all threads, and each thread's round-trip percentiles pooled.
void BM_RequestAckConcurrentIds(benchmark::State& state) {
  PtySetup setup;
  if (!setup.ready) {
    state.SkipWithError("could not connect the pty pair");
    return;
  }
  const int threads = static_cast<int>(state.range(0));
  constexpr int kPerThread = 200;
  const std::vector<protocol::MessageId> ids = {0x000400, 0x000018, 0x000105, 0x000304,
                                                0x000201, 0x000308, 0x000313, 0x000500};
  std::vector<double> micros;
  for (auto _ : state) {
    std::vector<std::vector<double>> per_thread(threads);
    std::atomic<int> failures{0};
    const auto start = Clock::now();
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t) {
      workers.emplace_back([&, t] {
        const uint8_t payload[] = {0x01, 0x00};
        for (int i = 0; i < kPerThread; ++i) {
          const auto begin = Clock::now();
          if (!setup.session->request_raw(ids[t % ids.size()], payload, 2).ok()) ++failures;
          per_thread[t].push_back(std::chrono::duration<double>(Clock::now() - begin).count() *
                                  1e6);
        }
      });
    }
    for (std::thread& w : workers) w.join();
    const std::chrono::duration<double> took = Clock::now() - start;
    if (failures > 0) {
      state.SkipWithError("some requests failed");
      return;
    }
    state.SetIterationTime(took.count());
    for (const auto& v : per_thread) micros.insert(micros.end(), v.begin(), v.end());
  }
  state.counters["requests_per_s"] = benchmark::Counter(
      static_cast<double>(threads * kPerThread), benchmark::Counter::kIsIterationInvariantRate);
  report_percentiles(state, std::move(micros));
}
BENCHMARK(BM_RequestAckConcurrentIds)
    ->Arg(1)
    ->Arg(4)
    ->Arg(8)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

// 0x000002 reports (section 3.1.1.2) back to back, as the pod sends them at 10 Hz.
std::vector<uint8_t> attitude_stream(size_t frames) {
  std::vector<uint8_t> stream;
  protocol::GimbalAttitude attitude;
  for (size_t i = 0; i < frames; ++i) {
    attitude.yaw_deg = static_cast<double>(i % 360) - 180.0;
    auto payload = protocol::encode_payload(attitude);
    protocol::FrameHeader header;
    header.destination = protocol::kHostAddress;
    header.source = protocol::kGimbalAddress;
    header.sequence = static_cast<uint8_t>(i);
    header.message_id = protocol::GimbalAttitude::kId;
    auto frame = protocol::encode_frame(header, payload->data(), payload->size,
                                        protocol::CrcCoverage::kHeaderExcluded);
    stream.insert(stream.end(), frame->data(), frame->data() + frame->size());
  }
  return stream;
}

void BM_DispatcherFeed(benchmark::State& state) {
  const size_t chunk = static_cast<size_t>(state.range(0));
  const std::vector<uint8_t> stream = attitude_stream(1000);
  Dispatcher dispatcher(protocol::CrcCoverage::kAuto, protocol::CodecOptions{});
  double yaw_sum = 0;
  dispatcher.on_frame([](const protocol::FrameView&) {});
  dispatcher.on<protocol::GimbalAttitude>(
      [&](const protocol::GimbalAttitude& a, const protocol::FrameView&) { yaw_sum += a.yaw_deg; });
  dispatcher.feed(stream.data(), stream.size());  // warm up: auto coverage locks
  const uint64_t frames_before = dispatcher.stats().parser.frames_good;
  const uint64_t allocations_before = g_allocations.load();
  for (auto _ : state) {
    for (size_t at = 0; at < stream.size(); at += chunk) {
      dispatcher.feed(stream.data() + at, std::min(chunk, stream.size() - at));
    }
  }
  benchmark::DoNotOptimize(yaw_sum);
  const double frames = static_cast<double>(dispatcher.stats().parser.frames_good - frames_before);
  state.counters["allocations_per_frame"] =
      static_cast<double>(g_allocations.load() - allocations_before) / frames;
  state.counters["frames_per_s"] = benchmark::Counter(frames, benchmark::Counter::kIsRate);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * stream.size()));
}
BENCHMARK(BM_DispatcherFeed)->Arg(1)->Arg(64)->Arg(4096);

}  // namespace
}  // namespace k40t::session

BENCHMARK_MAIN();
