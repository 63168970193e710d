// The rig of the conventions tests: the simulator (PodServer, in-process, on a fresh pty) playing
// some of the document's open readings (`--convention NAME=VALUE`), and the driver core
// (PodDriver) loaded with readings of its own, keeping the latest report of each kind it
// publishes. The simulator's model is the truth (true physical terms) the driver's output is
// compared with.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "eventually.h"
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/conventions.h"
#include "k40t_driver/sim/pod_server.h"
#include "pod_driver_test_support.h"
#include "sim_link_harness.h"

namespace k40t::driver::testing {

class ConventionsRig {
 public:
  // `pod` and `driver`: "NAME=VALUE" each; `tweak` changes the simulator's options first;
  // `before_start` registers the test's own handlers.
  ConventionsRig(const std::vector<std::string>& pod, const std::vector<std::string>& driver,
                 const std::function<void(sim::SimOptions&)>& tweak = {},
                 const std::function<void(PodDriver&)>& before_start = {}) {
    const std::string path = sim::testing::unique_pty_path();
    sim::SimOptions sim;
    sim.link = "pty://" + path;
    for (const std::string& c : pod) {
      const Status set = protocol::set_convention_assignment({sim.crc_coverage, sim.codec}, c);
      EXPECT_TRUE(set) << set.message();
    }
    if (tweak) tweak(sim);
    server_ = std::make_unique<sim::PodServer>(sim);
    const Status started = server_->start();
    EXPECT_TRUE(started) << started.message();

    DriverOptions o = options_for(path);
    for (const std::string& c : driver) {
      const Status set =
          protocol::set_convention_assignment({o.session.crc_coverage, o.session.codec}, c);
      EXPECT_TRUE(set) << set.message();
      o.conventions_from_parameters.insert(c.substr(0, c.find('=')));
    }
    driver_ = make_driver(o, [] { return system_now_ns(); });
    keep(attitude_);
    keep(camera_);
    keep(visible_);
    if (before_start) before_start(*driver_);
    EXPECT_TRUE(driver_->start());
    EXPECT_TRUE(test::eventually([&] { return latest(attitude_).has_value(); }))
        << "no attitude report through the driver";
  }
  ~ConventionsRig() {
    driver_->stop();
    server_->stop();
  }

  PodDriver& driver() { return *driver_; }
  sim::PodServer& pod() { return *server_; }
  std::optional<protocol::GimbalAttitude> attitude() { return latest(attitude_); }
  std::optional<protocol::CameraSystemStatus> camera() { return latest(camera_); }
  std::optional<protocol::VisibleStatus> visible() { return latest(visible_); }
  // The simulator's true joint angles (yaw right, pitch up positive).
  sim::YawPitchRoll true_joints() {
    sim::YawPitchRoll joints;
    server_->with_model([&](sim::PodModel& m) { joints = m.gimbal().pose().joint_deg; });
    return joints;
  }
  // The `conventions` diagnostic's entry for `name`.
  ConventionStatus reading(const std::string& name) {
    for (const ConventionStatus& s : driver_->conventions_report())
      if (s.name == name) return s;
    ADD_FAILURE() << "no reading " << name;
    return {};
  }
  bool contradicts(const std::string& name) {
    return test::eventually([&] { return !reading(name).contradiction.empty(); });
  }

 private:
  static StampNs system_now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
  }
  template <class Msg>
  void keep(std::optional<Msg>& slot) {
    driver_->on<Msg>([this, &slot](const Msg& m, StampNs) {
      std::lock_guard<std::mutex> lock(mutex_);
      slot = m;
    });
  }
  template <class Msg>
  std::optional<Msg> latest(const std::optional<Msg>& slot) {
    std::lock_guard<std::mutex> lock(mutex_);
    return slot;
  }

  std::unique_ptr<sim::PodServer> server_;
  std::unique_ptr<PodDriver> driver_;
  std::mutex mutex_;
  std::optional<protocol::GimbalAttitude> attitude_;
  std::optional<protocol::CameraSystemStatus> camera_;
  std::optional<protocol::VisibleStatus> visible_;
};

}  // namespace k40t::driver::testing
