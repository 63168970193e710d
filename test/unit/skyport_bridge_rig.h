// The rig of the SkyportBridge tests: the simulated SKYPORT adapter over an in-memory link to the
// bridge, with a fake pod behind the PodPort that records every call, can refuse, can hold a call
// (a pod that takes long, or is unplugged), and reports what a test tells it to.
#pragma once

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "k40t_driver/skyport/skyport_bridge.h"
#include "psdk_fake_transport.h"

namespace k40t::driver::skyport::bridge_testing {

using namespace psdk;
using psdk::sim::AdapterOptions;
using psdk::sim::AdapterSimulator;
using psdk::testing::FakeLink;

const Credentials kCredentials{"k40t_test", "123456", "0123456789abcdef0123456789abcdef",
                               "dev@example.com"};

inline bool eventually(const std::function<bool()>& condition) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  while (!condition()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

// Records every call; answers ok unless told to refuse.
class FakePod : public PodPort {
 public:
  std::vector<std::string> calls() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return calls_;
  }
  void set_recording(bool recording) {
    std::lock_guard<std::mutex> lock(mutex_);
    state_.recording = recording;
  }
  void refuse(bool refuse) { refuse_ = refuse; }
  // The gimbal's joints and attitude, REP 103 radians (pod_port.h); no attitude with nullopt.
  void set_gimbal(double pitch_rad, double yaw_rad, std::optional<double> attitude_pitch_rad,
                  std::optional<double> attitude_yaw_rad) {
    std::lock_guard<std::mutex> lock(mutex_);
    gimbal_ = {pitch_rad, yaw_rad, attitude_pitch_rad, attitude_yaw_rad};
  }
  // Every pod call waits until release() (a pod that takes long, or an unplugged one whose
  // driver waits for its timeout); `held()` counts the calls waiting now.
  void hold() {
    std::lock_guard<std::mutex> lock(gate_mutex_);
    held_ = true;
  }
  void release() {
    {
      std::lock_guard<std::mutex> lock(gate_mutex_);
      held_ = false;
    }
    gate_.notify_all();
  }
  int held() const { return waiting_; }
  // record/status went silent while recording: the port says "unknown".
  void lose_record_status() {
    std::lock_guard<std::mutex> lock(mutex_);
    state_.recording_known = false;
  }
  // A camera/upgrade_status message (CameraUpgradeStatus STATE_*).
  void report_repair(uint8_t state, uint8_t percent) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++state_.repair_status_count;
    state_.repair_state = state;
    state_.repair_percent = percent;
  }
  // camera/status: SD card (CameraStatus SD_*) and time-lapse interval.
  void set_sd(uint8_t state, double total_mb, double free_mb) {
    std::lock_guard<std::mutex> lock(mutex_);
    state_.sd_state = state;
    state_.sd_total_mb = total_mb;
    state_.sd_free_mb = free_mb;
  }
  void set_timelapse(uint8_t interval_s) {
    std::lock_guard<std::mutex> lock(mutex_);
    state_.photo_mode = 2;  // CameraStatus PHOTO_TIMELAPSE
    state_.timelapse_interval_s = interval_s;
  }
  // visible/status: the pod's hybrid zoom ratio (continuous zoom moves it).
  void report_zoom(double ratio) {
    std::lock_guard<std::mutex> lock(mutex_);
    state_.zoom_ratio = ratio;
  }
  // Like the pod: after a photo, capture commands are refused ("taking photo") for `storing`.
  void store_photos_for(std::chrono::milliseconds storing) { storing_ = storing; }
  void photo_stored() {
    std::lock_guard<std::mutex> lock(mutex_);
    storing_until_ = std::chrono::steady_clock::now();
  }
  // A photo/status message from the driver (PhotoStatus STATE_*).
  void report_photo(uint8_t state) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++state_.photo_status_count;
    state_.photo_state = state;
  }

  PodCall take_photo(bool stop) override {
    if (stop) return log("photo stop");
    PodCall r = capture("photo");
    std::lock_guard<std::mutex> lock(mutex_);
    if (r.ok) storing_until_ = std::chrono::steady_clock::now() + storing_;
    return r;
  }
  PodCall record(bool start) override {
    PodCall r = capture(start ? "record start" : "record stop");
    std::lock_guard<std::mutex> lock(mutex_);
    if (r.ok) state_.recording = start;
    return r;
  }
  PodCall set_photo_mode(uint8_t mode, uint8_t interval, uint8_t burst) override {
    PodCall r = capture("photo mode " + std::to_string(mode) + " " + std::to_string(interval) +
                        " " + std::to_string(burst));
    std::lock_guard<std::mutex> lock(mutex_);
    if (r.ok) {  // as camera/status then reports it
      state_.photo_mode = mode;
      state_.timelapse_interval_s = interval;
      state_.burst_count = burst;
    }
    return r;
  }
  PodCall set_video_mode(bool video) override {
    PodCall r = capture(video ? "video" : "photo mode");
    r.photo_in_progress = false;  // dynamic_reconfigure says only "not applied"
    return r;
  }
  PodCall set_metering(int m) override { return log("metering " + std::to_string(m)); }
  PodCall set_zoom(double ratio) override {
    char text[32];
    std::snprintf(text, sizeof text, "zoom %.2f", ratio);
    PodCall r = log(text);
    if (r.ok) report_zoom(ratio);
    return r;
  }
  PodCall zoom(PodZoom a) override { return log("zoom action " + std::to_string(int(a))); }
  PodCall focus(PodFocus m, uint16_t, uint16_t, uint16_t, uint16_t) override {
    return log("focus " + std::to_string(int(m)));
  }
  PodCall format_sd() override { return capture("format"); }
  PodCall set_angle(double pitch, double yaw) override {
    char text[64];
    std::snprintf(text, sizeof text, "angle %.4f %.4f", pitch, yaw);
    const PodCall r = log(text);
    if (r.ok) move_gimbal(pitch, yaw);
    return r;
  }
  PodCall set_rate(double pitch, double yaw) override {
    char text[64];
    std::snprintf(text, sizeof text, "rate %.4f %.4f", pitch, yaw);
    return log(text);
  }
  PodCall center() override {
    const PodCall r = log("center");
    if (r.ok) move_gimbal(0, 0);
    return r;
  }
  PodCall calibrate() override { return log("calibrate"); }
  PodCall set_palette(int p) override { return log("palette " + std::to_string(p)); }
  PodCall set_image_mode(int m) override { return log("image mode " + std::to_string(m)); }
  PodCall measure_range(double& range_m) override {
    range_m = 123.4;
    return log("measure");
  }
  PodSnapshot snapshot() const override {
    std::lock_guard<std::mutex> lock(mutex_);
    PodSnapshot s = state_;
    s.have_joints = s.have_camera = s.have_visible = true;
    s.pitch_rad = gimbal_.pitch_rad;
    s.yaw_rad = gimbal_.yaw_rad;
    s.have_attitude = gimbal_.attitude_pitch_rad && gimbal_.attitude_yaw_rad;
    s.attitude_pitch_rad = gimbal_.attitude_pitch_rad.value_or(0);
    s.attitude_yaw_rad = gimbal_.attitude_yaw_rad.value_or(0);
    return s;
  }

 private:
  // The joints arrive at once; the attitude keeps its offset from them (the aircraft's heading).
  void move_gimbal(double pitch_rad, double yaw_rad) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (gimbal_.attitude_pitch_rad) *gimbal_.attitude_pitch_rad += pitch_rad - gimbal_.pitch_rad;
    if (gimbal_.attitude_yaw_rad) *gimbal_.attitude_yaw_rad += yaw_rad - gimbal_.yaw_rad;
    gimbal_.pitch_rad = pitch_rad;
    gimbal_.yaw_rad = yaw_rad;
  }
  PodCall log(const std::string& call) {
    wait_gate();
    std::lock_guard<std::mutex> lock(mutex_);
    calls_.push_back(call);
    return {!refuse_, refuse_ ? "refused" : "ok"};
  }
  void wait_gate() {
    std::unique_lock<std::mutex> lock(gate_mutex_);
    ++waiting_;
    gate_.wait(lock, [this] { return !held_; });
    --waiting_;
  }
  // A call the pod refuses while it stores a photo.
  PodCall capture(const std::string& call) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (std::chrono::steady_clock::now() < storing_until_) {
        calls_.push_back(call + " (refused: taking photo)");
        return {false, "refused by the pod: taking photo (response code 0x0203)", true};
      }
    }
    return log(call);
  }
  mutable std::mutex mutex_;
  std::chrono::milliseconds storing_{0};
  std::chrono::steady_clock::time_point storing_until_{};
  std::vector<std::string> calls_;
  PodSnapshot state_;
  struct Gimbal {
    double pitch_rad, yaw_rad;
    std::optional<double> attitude_pitch_rad, attitude_yaw_rad;
  };
  // REP 103: looking 30 degrees down, turned 20 degrees right; the aircraft heads 90 degrees
  // east, so the pod looks 110 degrees from north, 30 degrees down.
  Gimbal gimbal_{30 * M_PI / 180, -20 * M_PI / 180, 30 * M_PI / 180, -110 * M_PI / 180};
  std::atomic<bool> refuse_{false};
  std::mutex gate_mutex_;
  std::condition_variable gate_;
  bool held_ = false;
  std::atomic<int> waiting_{0};
};

struct Rig {
  explicit Rig(const Credentials& payload_credentials = kCredentials,
               double photo_storing_s = BridgeOptions{}.photo_storing_s,
               const std::function<void(BridgeOptions&)>& tweak = nullptr,
               psdk::sim::PayloadReading reading = psdk::sim::PayloadReading::kDjiHeaders) {
    auto adapter_link = std::make_unique<FakeLink>();
    auto payload_link = std::make_unique<FakeLink>();
    FakeLink::pair(*adapter_link, *payload_link);
    SessionOptions options;
    options.aes_key = derive_aes_key(payload_credentials);
    payload = std::make_unique<Session>(std::move(payload_link), options);
    BridgeOptions bridge_options;
    bridge_options.app_key = payload_credentials.app_key;
    bridge_options.photo_storing_s = photo_storing_s;
    if (tweak) tweak(bridge_options);
    bridge = std::make_unique<SkyportBridge>(*payload, pod, bridge_options, nullptr, nullptr);
    AdapterOptions adapter_options;
    adapter_options.credentials = kCredentials;
    adapter_options.reading = reading;
    adapter_options.encryption = payload_credentials.app_key == kCredentials.app_key;
    adapter = std::make_unique<AdapterSimulator>(std::move(adapter_link), adapter_options);
    EXPECT_TRUE(payload->start());
    EXPECT_TRUE(adapter->start());
  }
  ~Rig() {
    pod.release();    // a held pod call must not keep the bridge's worker from stopping
    adapter->stop();  // both sides stop before either is destroyed
    payload->stop();
  }
  // The ACK of `command`: its code, and the decoded reply.
  template <class Cmd>
  Result<typename Cmd::Ack> ask(const Cmd& command, AckResult* raw = nullptr) {
    return adapter->session().request(command, raw);
  }
  uint8_t code_of(CommandKey key, const std::vector<uint8_t>& data = {}) {
    return adapter->session().request_raw(key, data.data(), data.size()).code();
  }

  FakePod pod;
  std::unique_ptr<Session> payload;
  std::unique_ptr<SkyportBridge> bridge;
  std::unique_ptr<AdapterSimulator> adapter;
};

inline bool has_call(const FakePod& pod, const std::string& call) {
  for (const auto& c : pod.calls()) {
    if (c == call) return true;
  }
  return false;
}

}  // namespace k40t::driver::skyport::bridge_testing
