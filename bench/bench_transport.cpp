// Round-trip latency through the transports: the client sends a message, the server's receive
// callback echoes it, the client waits until every byte is back. Each iteration is timed by hand
// (UseManualTime) and the p50/p99/max of the round trips are reported as counters in µs.
//
// The pty pair (pty:// on one side, serial:// on its symlink on the other) is the simulator link;
// UDP and TCP on 127.0.0.1 are there for comparison. BM_Close* time close() itself, which must be
// prompt both on a live link and during a reconnect back-off.
#include <benchmark/benchmark.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../test/unit/transport_test_support.h"  // free ports, scratch dirs, waiting
#include "k40t_driver/transport/transport.h"
#include "percentiles.h"

namespace k40t::transport {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::chrono::seconds kDeadline{10};

enum class Link { kPty, kUdp, kTcp };

bool wait_until(const std::function<bool()>& condition) {
  return testing::eventually(condition, kDeadline);
}

std::unique_ptr<Transport> make(const std::string& url) {
  auto made = make_transport(url);
  return made ? std::move(made).value() : nullptr;
}

// "<scheme>-server://127.0.0.1:<free port>" and "<scheme>://" to the same address.
std::pair<std::string, std::string> loopback_urls(const std::string& scheme, int socket_type) {
  const std::string address =
      "127.0.0.1:" + std::to_string(testing::free_loopback_port(socket_type));
  return {scheme + "-server://" + address, scheme + "://" + address};
}

// A server that echoes everything and a client that counts what comes back.
class EchoPair {
 public:
  explicit EchoPair(Link link) {
    std::string server_url;
    std::string client_url;
    switch (link) {
      case Link::kPty:
        server_url = "pty://" + dir_.file("pod");
        client_url = "serial://" + dir_.file("pod") + "?baud=115200";
        break;
      case Link::kUdp:
        std::tie(server_url, client_url) = loopback_urls("udp", SOCK_DGRAM);
        break;
      case Link::kTcp:
        std::tie(server_url, client_url) = loopback_urls("tcp", SOCK_STREAM);
        break;
    }
    server_ = make(server_url);
    client_ = make(client_url);
    if (!server_ || !client_) return;
    server_->set_receive_callback([this](const uint8_t* data, size_t size) {
      if (!server_->send(data, size)) echo_failed_ = true;
    });
    client_->set_receive_callback([this](const uint8_t* /*data*/, size_t size) {
      std::lock_guard<std::mutex> lock(mutex_);
      received_ += size;
      arrived_.notify_one();
    });
    // The pty must exist before the serial side can open it, and a udp-server must be bound
    // before the first datagram; a tcp-server connects only once it has accepted the client.
    if (!server_->open()) return;
    if (link != Link::kTcp && !wait_connected(*server_)) return;
    if (!client_->open() || !wait_connected(*client_)) return;
    ready_ = wait_connected(*server_);
  }

  ~EchoPair() {
    client_.reset();
    server_.reset();
  }

  bool ready() const { return ready_; }
  bool echo_failed() const { return echo_failed_; }

  // Sends `message` and waits for all of it to come back.
  bool round_trip(const std::vector<uint8_t>& message) {
    std::unique_lock<std::mutex> lock(mutex_);
    received_ = 0;
    lock.unlock();
    if (!client_->send(message.data(), message.size())) return false;
    lock.lock();
    return arrived_.wait_for(lock, kDeadline, [&] { return received_ >= message.size(); });
  }

 private:
  static bool wait_connected(const Transport& transport) {
    return wait_until([&] { return transport.state() == LinkState::kConnected; });
  }

  testing::ScratchDir dir_;
  std::unique_ptr<Transport> server_;
  std::unique_ptr<Transport> client_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  size_t received_ = 0;
  bool ready_ = false;
  std::atomic<bool> echo_failed_{false};
};

using bench::report_percentiles;

void BM_RoundTrip(benchmark::State& state, Link link) {
  EchoPair pair(link);
  if (!pair.ready()) {
    state.SkipWithError("could not connect the pair");
    return;
  }
  std::vector<uint8_t> message(static_cast<size_t>(state.range(0)));
  for (size_t i = 0; i < message.size(); ++i) message[i] = static_cast<uint8_t>(i * 31 + 7);
  std::vector<double> micros;
  micros.reserve(1 << 16);
  for (auto _ : state) {
    const auto start = Clock::now();
    if (!pair.round_trip(message)) {
      state.SkipWithError(pair.echo_failed() ? "the echo failed" : "no echo within the deadline");
      return;
    }
    const std::chrono::duration<double> took = Clock::now() - start;
    state.SetIterationTime(took.count());
    micros.push_back(took.count() * 1e6);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * state.range(0) * 2);
  report_percentiles(state, std::move(micros));
}

// A short command, a typical status frame, a burst, and more than one tty read (4 KiB).
void message_sizes(benchmark::internal::Benchmark* benchmark) {
  for (int size : {16, 64, 1024, 16384}) benchmark->Arg(size);
  benchmark->UseManualTime()->Unit(benchmark::kMicrosecond);
}
BENCHMARK_CAPTURE(BM_RoundTrip, pty_serial, Link::kPty)->Apply(message_sizes);
BENCHMARK_CAPTURE(BM_RoundTrip, udp, Link::kUdp)->Apply(message_sizes);
BENCHMARK_CAPTURE(BM_RoundTrip, tcp, Link::kTcp)->Apply(message_sizes);

// Times close() on transports that `prepare` brings to the state under test.
void time_close(benchmark::State& state,
                const std::function<std::unique_ptr<Transport>()>& prepare) {
  std::vector<double> micros;
  for (auto _ : state) {
    auto transport = prepare();
    if (!transport) {
      state.SkipWithError("could not prepare the transport");
      return;
    }
    const auto start = Clock::now();
    transport->close();
    const std::chrono::duration<double> took = Clock::now() - start;
    state.SetIterationTime(took.count());
    micros.push_back(took.count() * 1e6);
  }
  report_percentiles(state, std::move(micros));
}

// A transport for `url` that has reached `wanted`, or null.
std::unique_ptr<Transport> open_until(const std::string& url, LinkState wanted,
                                      const ReconnectPolicy& policy = {}) {
  auto transport = make(url);
  if (!transport) return nullptr;
  transport->set_reconnect_policy(policy);
  if (!transport->open() || !wait_until([&] { return transport->state() == wanted; })) {
    return nullptr;
  }
  return transport;
}

// close() on a connected serial:// client (pty on the other side): the I/O thread sits in poll().
void BM_CloseConnected(benchmark::State& state) {
  testing::ScratchDir dir;
  const std::string path = dir.file("pod");
  auto pod = open_until("pty://" + path, LinkState::kConnected);
  time_close(state, [&]() -> std::unique_ptr<Transport> {
    return pod ? open_until("serial://" + path, LinkState::kConnected) : nullptr;
  });
}
BENCHMARK(BM_CloseConnected)->UseManualTime()->Unit(benchmark::kMicrosecond);

// close() while the client waits out a long back-off for a device that does not exist.
void BM_CloseDuringBackoff(benchmark::State& state) {
  ReconnectPolicy slow;
  slow.initial_delay = std::chrono::seconds(30);
  slow.max_delay = slow.initial_delay;
  time_close(state, [&] {
    return open_until("serial:///nonexistent/k40t_bench_device", LinkState::kReconnecting, slow);
  });
}
BENCHMARK(BM_CloseDuringBackoff)->UseManualTime()->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace k40t::transport

BENCHMARK_MAIN();
