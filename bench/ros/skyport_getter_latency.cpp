// Adapter-side ACK latency of the SKYPORT bridge's getters while a pod call is blocked for 2 s
// (the deadline case: before, such a getter waited behind the call on the bridge's single
// worker). The bridge (ROS-free) and the simulated adapter talk over an in-memory link with AES on,
// so the figure is the bridge's own answer time without UART wire time (at 115200 baud a 30-byte
// ACK adds ~2.6 ms). Every 2 s the adapter starts a gimbal calibration that the pod holds for 2 s,
// so the worker is always busy; meanwhile it polls getters as DJI Pilot does, one after the other,
// and times each from the request to its ACK. Prints p50/p90/p99/max; target p99 <= 20 ms.
//   k40t_skyport_getter_latency [seconds=10]
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "../../test/unit/psdk_fake_transport.h"
#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "k40t_driver/skyport/skyport_bridge.h"

namespace {

using namespace k40t;
using namespace k40t::psdk;
using namespace k40t::driver::skyport;
using Clock = std::chrono::steady_clock;

// Whether the getter G was answered with an ACK.
template <class G>
bool answered(Session& session) {
  return static_cast<bool>(session.request(G{}));
}
// The getters DJI Pilot polls, asked one after the other.
constexpr std::array<bool (*)(Session&), 6> kPolledGetters = {
    answered<GetGimbalState>,       answered<GetRecordState>,    answered<GetSdCardInfo>,
    answered<GetDigitalZoomFactor>, answered<GetShootPhotoMode>, answered<GetWidgetGroupData>};

// A pod whose calibration takes 2 s to answer (a pod call blocked, as during an outage the
// driver's service waits for its timeout); everything else answers at once.
class SlowPod : public PodPort {
 public:
  PodCall take_photo(bool) override { return ok(); }
  PodCall record(bool) override { return ok(); }
  PodCall set_photo_mode(uint8_t, uint8_t, uint8_t) override { return ok(); }
  PodCall set_video_mode(bool) override { return ok(); }
  PodCall set_metering(int) override { return ok(); }
  PodCall set_zoom(double) override { return ok(); }
  PodCall zoom(PodZoom) override { return ok(); }
  PodCall focus(PodFocus, uint16_t, uint16_t, uint16_t, uint16_t) override { return ok(); }
  PodCall format_sd() override { return ok(); }
  PodCall set_angle(double, double) override { return ok(); }
  PodCall set_rate(double, double) override { return ok(); }
  PodCall center() override { return ok(); }
  PodCall calibrate() override {
    std::this_thread::sleep_for(std::chrono::seconds(2));
    return ok();
  }
  PodCall set_palette(int) override { return ok(); }
  PodCall set_image_mode(int) override { return ok(); }
  PodCall measure_range(double& range_m) override {
    range_m = 100;
    return ok();
  }
  PodSnapshot snapshot() const override {
    PodSnapshot s;
    s.have_joints = s.have_camera = s.have_visible = true;
    s.sd_state = 0;
    s.sd_total_mb = 64000;
    s.sd_free_mb = 32000;
    s.state_age_s = 0.1;
    return s;
  }

 private:
  static PodCall ok() { return {true, "ok"}; }
};

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const size_t i = std::min(v.size() - 1, static_cast<size_t>(p / 100.0 * (v.size() - 1) + 0.5));
  return v[i];
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 10.0;
  const Credentials credentials{"k40t_bench", "123456", "0123456789abcdef0123456789abcdef",
                                "dev@example.com"};
  auto adapter_link = std::make_unique<testing::FakeLink>();
  auto payload_link = std::make_unique<testing::FakeLink>();
  testing::FakeLink::pair(*adapter_link, *payload_link);
  SessionOptions session_options;
  session_options.aes_key = derive_aes_key(credentials);
  Session payload(std::move(payload_link), session_options);
  SlowPod pod;
  BridgeOptions bridge_options;
  bridge_options.app_key = credentials.app_key;
  SkyportBridge bridge(payload, pod, bridge_options, nullptr, nullptr);
  sim::AdapterOptions adapter_options;
  adapter_options.credentials = credentials;
  sim::AdapterSimulator adapter(std::move(adapter_link), adapter_options);
  if (!payload.start() || !adapter.start()) {
    std::fprintf(stderr, "could not start the link\n");
    return 1;
  }
  Session& session = adapter.session();

  std::atomic<uint64_t> calibrations_answered{0};
  std::vector<double> latencies_ms;
  uint64_t failures = 0;
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  auto next_calibration = Clock::now();
  size_t turn = 0;
  while (Clock::now() < end) {
    if (Clock::now() >= next_calibration) {  // keep the worker blocked in the pod
      Data none;
      session.request_async(
          CalibrateGimbal::key(), none,
          [&calibrations_answered](const AckResult&) { ++calibrations_answered; });
      next_calibration += std::chrono::seconds(2);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the job has started
    }
    const auto t0 = Clock::now();
    const bool ok = kPolledGetters[turn++ % kPolledGetters.size()](session);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    if (ok) {
      latencies_ms.push_back(ms);
    } else {
      ++failures;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));  // DJI Pilot polls, not floods
  }
  adapter.stop();
  payload.stop();
  if (latencies_ms.empty()) {
    std::printf("skyport getter ACK latency: no getter answered (%llu failures)\n",
                static_cast<unsigned long long>(failures));
    return 1;
  }
  const double p99 = percentile(latencies_ms, 99);
  std::printf(
      "skyport getter ACK latency while a pod call is blocked 2 s (%zu getters, %llu unanswered, "
      "%llu calibrations answered, %.0f s):\n"
      "  p50 %.3f ms  p90 %.3f ms  p99 %.3f ms  max %.3f ms  (target p99 <= 20 ms: %s)\n",
      latencies_ms.size(), static_cast<unsigned long long>(failures),
      static_cast<unsigned long long>(calibrations_answered.load()), seconds,
      percentile(latencies_ms, 50), percentile(latencies_ms, 90), p99,
      *std::max_element(latencies_ms.begin(), latencies_ms.end()), p99 <= 20.0 ? "met" : "MISSED");
  return 0;
}
