// SkyportBridge (ROS-free) against the simulated SKYPORT adapter over an in-memory link, with a
// fake pod behind the PodPort: what the adapter's commands do to the pod, the return codes, the
// signs, and the power-off order (the pod's recording stops before the ACK says ready).
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../../unit/psdk_fake_transport.h"
#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "k40t_driver/ros/skyport/skyport_bridge.h"

namespace k40t::driver::skyport {
namespace {

using namespace psdk;
using psdk::sim::AdapterOptions;
using psdk::sim::AdapterSimulator;
using psdk::testing::FakeLink;

const Credentials kCredentials{"k40t_test", "123456", "0123456789abcdef0123456789abcdef",
                               "dev@example.com"};

bool eventually(const std::function<bool()>& condition) {
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
    return capture("photo mode " + std::to_string(mode) + " " + std::to_string(interval) + " " +
                   std::to_string(burst));
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
    return log(text);
  }
  PodCall zoom(PodZoom a) override { return log("zoom action " + std::to_string(int(a))); }
  PodCall focus(PodFocus m, uint16_t, uint16_t, uint16_t, uint16_t) override {
    return log("focus " + std::to_string(int(m)));
  }
  PodCall format_sd() override { return capture("format"); }
  PodCall set_angle(double pitch, double yaw) override {
    char text[64];
    std::snprintf(text, sizeof text, "angle %.4f %.4f", pitch, yaw);
    return log(text);
  }
  PodCall set_rate(double pitch, double yaw) override {
    char text[64];
    std::snprintf(text, sizeof text, "rate %.4f %.4f", pitch, yaw);
    return log(text);
  }
  PodCall center() override { return log("center"); }
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
    s.pitch_rad = 30 * M_PI / 180;  // REP 103: looking 30 degrees down
    s.yaw_rad = -20 * M_PI / 180;   // turned 20 degrees right
    return s;
  }

 private:
  PodCall log(const std::string& call) {
    std::lock_guard<std::mutex> lock(mutex_);
    calls_.push_back(call);
    return {!refuse_, refuse_ ? "refused" : "ok"};
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
  std::atomic<bool> refuse_{false};
};

struct Rig {
  explicit Rig(const Credentials& payload_credentials = kCredentials,
               double photo_storing_s = BridgeOptions{}.photo_storing_s) {
    auto adapter_link = std::make_unique<FakeLink>();
    auto payload_link = std::make_unique<FakeLink>();
    FakeLink::pair(*adapter_link, *payload_link);
    SessionOptions options;
    options.aes_key = derive_aes_key(payload_credentials);
    payload = std::make_unique<Session>(std::move(payload_link), options);
    BridgeOptions bridge_options;
    bridge_options.app_key = payload_credentials.app_key;
    bridge_options.photo_storing_s = photo_storing_s;
    bridge = std::make_unique<SkyportBridge>(*payload, pod, bridge_options, nullptr, nullptr);
    AdapterOptions adapter_options;
    adapter_options.credentials = kCredentials;
    adapter_options.encryption = payload_credentials.app_key == kCredentials.app_key;
    adapter = std::make_unique<AdapterSimulator>(std::move(adapter_link), adapter_options);
    EXPECT_TRUE(payload->start());
    EXPECT_TRUE(adapter->start());
  }
  ~Rig() {
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

bool has_call(const FakePod& pod, const std::string& call) {
  for (const auto& c : pod.calls()) {
    if (c == call) return true;
  }
  return false;
}

TEST(SkyportBridge, IdentityAndPayloadStatePass) {
  Rig rig;
  const psdk::sim::IdentityResult r = rig.adapter->verify_identity();
  EXPECT_TRUE(r.passed) << r.detail;
  const psdk::sim::CheckReport report = rig.adapter->check_payload_state();
  EXPECT_TRUE(report.passed()) << report.summary();
}

TEST(SkyportBridge, IdentityFailsWithAnotherKey) {
  Credentials other = kCredentials;
  other.app_key = "ffffffffffffffffffffffffffffffff";
  Rig rig(other);
  const psdk::sim::IdentityResult r = rig.adapter->verify_identity();
  EXPECT_TRUE(r.answered);
  EXPECT_FALSE(r.passed);
}

TEST(SkyportBridge, ShootPhotoDrivesThePodAndReportsItsRefusal) {
  Rig rig;
  ShootPhoto photo;
  AckResult raw;
  ASSERT_TRUE(rig.ask(photo, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "photo"));
  rig.pod.refuse(true);
  ASSERT_TRUE(rig.ask(photo, &raw));
  EXPECT_EQ(raw.code(), 0x01);  // never a made-up success
}

// PhotoStatus STATE_* (msg/PhotoStatus.msg).
constexpr uint8_t kPhotoTaken = 0, kSingleInProgress = 5;

bool single_shooting(Rig& rig) {
  const Result<ShootPhotoStateAck> state = rig.ask(GetShootPhotoState{});
  EXPECT_TRUE(state && state->code == AckCode::kOk);
  return state && state->state.shooting_single;
}

TEST(SkyportBridge, PhotoStateIsIdleUntilAPhotoIsTaken) {
  Rig rig;
  EXPECT_FALSE(single_shooting(rig));
}

TEST(SkyportBridge, PhotoStateFollowsThePodsPhotoStatus) {
  Rig rig(kCredentials, 60.0);        // the bound never ends it here: the pod's status does
  rig.pod.report_photo(kPhotoTaken);  // an earlier photo's status does not end this one
  ASSERT_TRUE(rig.ask(ShootPhoto{}));
  EXPECT_TRUE(single_shooting(rig));
  rig.pod.report_photo(kSingleInProgress);
  EXPECT_TRUE(single_shooting(rig));
  rig.pod.report_photo(kPhotoTaken);
  EXPECT_FALSE(single_shooting(rig));
}

TEST(SkyportBridge, PhotoStateIsShootingWhileThePodRefusesForThePhoto) {
  Rig rig(kCredentials, 60.0);
  rig.pod.store_photos_for(std::chrono::hours(1));
  ASSERT_TRUE(rig.ask(ShootPhoto{}));
  EXPECT_TRUE(single_shooting(rig));
  RecordVideo record;
  AckResult raw;
  ASSERT_TRUE(rig.ask(record, &raw));
  EXPECT_EQ(raw.code(), 0x01);  // refused: still storing
  EXPECT_TRUE(has_call(rig.pod, "record start (refused: taking photo)"));
  EXPECT_TRUE(single_shooting(rig));
  rig.pod.photo_stored();
  ASSERT_TRUE(rig.ask(record, &raw));
  EXPECT_EQ(raw.code(), 0x00);         // accepted: the pod stores nothing any more...
  EXPECT_FALSE(single_shooting(rig));  // ...so nothing is in progress
}

TEST(SkyportBridge, PhotoStateEndsAfterTheStoringBoundWithoutStatus) {
  Rig rig(kCredentials, 0.2);
  ASSERT_TRUE(rig.ask(ShootPhoto{}));
  EXPECT_TRUE(single_shooting(rig));
  EXPECT_TRUE(eventually([&] { return !single_shooting(rig); }));
}

// The adapter's own camera check, against a pod that refuses capture commands while it stores a
// photo (shorter than the bridge's bound): every step passes, as DJI Pilot would see it.
TEST(SkyportBridge, CameraCheckPassesAgainstAPodStoringItsPhoto) {
  Rig rig(kCredentials, 1.0);
  rig.pod.store_photos_for(std::chrono::milliseconds(300));
  const psdk::sim::CheckReport report = rig.adapter->check_camera();
  EXPECT_TRUE(report.passed()) << report.summary();
  EXPECT_NE(report.summary().find("shooting: single"), std::string::npos) << report.summary();
}

TEST(SkyportBridge, GimbalAnglesAreConvertedToRep103) {
  Rig rig;
  ControlGimbalAngle angle;  // DJI: pitch -30 = down, yaw +20 = right
  angle.pitch_deg = -30;
  angle.yaw_deg = 20;
  AckResult raw;
  ASSERT_TRUE(rig.ask(angle, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "angle 0.5236 -0.3491"));
  angle.roll_deg = 10;  // the pod takes no roll command
  ASSERT_TRUE(rig.ask(angle, &raw));
  EXPECT_EQ(raw.code(), 0x01);
  // And back: the pod's pose in DJI signs.
  const Result<GimbalStateAck> state = rig.ask(GetGimbalState{});
  ASSERT_TRUE(state) << state.error();
  EXPECT_NEAR(state->angles.pitch_deg, -30, 0.1);
  EXPECT_NEAR(state->angles.yaw_deg, 20, 0.1);
  EXPECT_EQ(state->mode, GimbalStateMode::kFollowing);
}

TEST(SkyportBridge, OpticalTimesDigitalZoomIsThePodsHybridZoom) {
  Rig rig;
  SetOpticalZoomFocalLength focal;
  focal.focal_length_mm = 9.4;  // 2x of the 4.7 mm telephoto
  AckResult raw;
  ASSERT_TRUE(rig.ask(focal, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  SetDigitalZoomFactor digital;
  digital.factor_x = 3;
  ASSERT_TRUE(rig.ask(digital, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "zoom 6.00"));
  focal.focal_length_mm = 100;  // beyond 11x optical
  ASSERT_TRUE(rig.ask(focal, &raw));
  EXPECT_EQ(raw.code(), 0x01);
}

TEST(SkyportBridge, WhatThePodCannotDoIsUnsupported) {
  Rig rig;
  EXPECT_EQ(rig.code_of(SetFocusRing::key(), {0x10, 0x00}), 0x02);
  EXPECT_EQ(rig.code_of(SetGimbalMode::key(), {0x00}), 0x02);  // free mode
  EXPECT_EQ(rig.code_of(SetGimbalMode::key(), {0x02}), 0x00);  // following
  EXPECT_EQ(rig.code_of(CommandKey{0x04, 0x50}), 0x02);        // not in the document
  EXPECT_TRUE(rig.pod.calls().empty());
}

TEST(SkyportBridge, PowerOffStopsRecordingBeforeAckingReady) {
  Rig rig;
  rig.pod.set_recording(true);
  rig.adapter->announce_power_off();
  ASSERT_TRUE(eventually([&] { return rig.adapter->stats().last_power_off_ready; }));
  EXPECT_TRUE(has_call(rig.pod, "record stop"));
  EXPECT_TRUE(rig.bridge->stats().power_off_ready);
}

TEST(SkyportBridge, PowerOffIsNotReadyWhileThePodKeepsRecording) {
  Rig rig;
  rig.pod.set_recording(true);
  rig.pod.refuse(true);
  rig.adapter->announce_power_off();
  const uint64_t acks = rig.adapter->stats().battery_acks;
  ASSERT_TRUE(eventually([&] { return rig.adapter->stats().battery_acks >= acks + 2; }));
  EXPECT_FALSE(rig.adapter->stats().last_power_off_ready);
  EXPECT_TRUE(has_call(rig.pod, "record stop"));
}

TEST(SkyportBridge, WidgetsDriveThePod) {
  Rig rig;
  const Result<WidgetListLengthAck> length = rig.ask(GetWidgetListLength{});
  ASSERT_TRUE(length);
  EXPECT_EQ(length->count, 4);
  GetWidgetListData which;
  which.index = 0;
  const Result<WidgetListDataAck> palette = rig.ask(which);
  ASSERT_TRUE(palette);
  EXPECT_EQ(palette->type, WidgetType::kChooseList);
  EXPECT_EQ(palette->name, "Palette");
  SetWidgetValue set;
  set.widget = {WidgetType::kChooseList, 0, 4};  // iron red, the pod's palette 5
  AckResult raw;
  ASSERT_TRUE(rig.ask(set, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "palette 5"));
  set.widget = {WidgetType::kButton, 2, 1};  // laser ranging: the result in the floating window
  ASSERT_TRUE(rig.ask(set, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(eventually([&] {
    for (const auto& m : rig.adapter->floating_window_messages())
      if (m.find("123.4 m") != std::string::npos) return true;
    return false;
  }));
  GetWidgetGroupData group;
  const Result<WidgetGroupDataAck> values = rig.ask(group);
  ASSERT_TRUE(values);
  EXPECT_EQ(values->count, 4);
  EXPECT_EQ(values->widgets[0].value, 4);
}

}  // namespace
}  // namespace k40t::driver::skyport
