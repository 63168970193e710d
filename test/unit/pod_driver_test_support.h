// What the PodDriver tests share: a driver on a fresh pty against a FakePod, with the periodic
// duties off unless a test turns them on, and readers of the time-sync frames it sends.
#pragma once

#include <unistd.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "fake_pod.h"
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::driver::testing {

using std::chrono::milliseconds;

constexpr StampNs kFixedNow = 1'700'000'000'000'000'000;

inline std::string unique_pty(const char* name) {
  return "/tmp/k40t_unit_" + std::string(name) + "_" + std::to_string(::getpid());
}

inline DriverOptions options_for(const std::string& pty) {
  DriverOptions o;
  o.device = "serial://" + pty;
  o.baud = 115200;
  o.time_sync_period_s = 0;  // tests that want it turn it on
  o.laser_target_period_s = 0;
  o.session.ack_timeout = milliseconds(100);
  return o;
}

inline std::unique_ptr<PodDriver> make_driver(
    const DriverOptions& o, PodDriver::Clock clock = [] { return kFixedNow; }) {
  Result<std::unique_ptr<PodDriver>> driver = PodDriver::create(o, std::move(clock));
  EXPECT_TRUE(driver.is_ok()) << driver.error();
  return std::move(driver.value());
}

// The driver opens the pty in the background (and may flush what came before): send reports
// until one has been received.
inline void wait_until_linked(FakePod& pod, PodDriver& driver) {
  for (int i = 0; i < 150 && driver.stats().session.parser.frames_good == 0; ++i) {
    pod.send(protocol::GimbalAttitude{});
    std::this_thread::sleep_for(milliseconds(20));
  }
  ASSERT_GT(driver.stats().session.parser.frames_good, 0u) << "the driver never received a frame";
}

// make_driver, started and linked to `pod`.
inline std::unique_ptr<PodDriver> started_driver(
    FakePod& pod, const DriverOptions& o, PodDriver::Clock clock = [] { return kFixedNow; }) {
  std::unique_ptr<PodDriver> driver = make_driver(o, std::move(clock));
  EXPECT_TRUE(driver->start().is_ok());
  wait_until_linked(pod, *driver);
  return driver;
}

inline std::vector<SentFrame> wait_for_time_syncs(FakePod& pod, size_t n) {
  pod.wait_for(FakePod::count_of(protocol::TimeSyncRequest::kId, n), milliseconds(3000));
  return pod.frames_with_id(protocol::TimeSyncRequest::kId);
}

// The time a sync frame sets the pod to (ms since the epoch).
inline std::optional<int64_t> time_sync_ms(const SentFrame& frame) {
  Result<protocol::TimeSyncRequest> sync = protocol::decode_payload<protocol::TimeSyncRequest>(
      frame.payload.data(), frame.payload.size());
  EXPECT_TRUE(sync.is_ok()) << sync.error();
  if (!sync) return std::nullopt;
  return sync->unix_time_ms;
}

inline int64_t system_now_ms() {
  return std::chrono::duration_cast<milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace k40t::driver::testing
