// The rig of the simulated SKYPORT adapter's tests (test_psdk_adapter_sim.cpp): a minimal,
// well-behaved payload built on psdk::Session (the role the SKYPORT bridge plays with the real pod
// behind it), linked to an AdapterSimulator over a pair of fake links.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "eventually.h"
#include "k40t_driver/psdk/identity.h"
#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "psdk_fake_transport.h"

namespace k40t::psdk::sim::testing {

using k40t::psdk::testing::FakeLink;
using k40t::test::eventually;

inline const Credentials kCredentials = {"K40T bridge", "123456",
                                         "0123456789abcdef0123456789abcdef", "dev@example.com"};

// A small, well-behaved payload: answers the payload-state, camera and gimbal sets from its own
// state and counts the pushes it receives.
class TestPayload {
 public:
  TestPayload(std::unique_ptr<FakeLink> link, const Credentials& credentials,
              bool handle_camera_and_gimbal = true) {
    SessionOptions options;
    options.aes_key = derive_aes_key(credentials);
    session_ = std::make_unique<Session>(std::move(link), options);
    Session& s = *session_;
    const std::string app_key = credentials.app_key;
    s.handle<IdentityVerification>([app_key](const IdentityVerification& c) {
      return answer_identity_verification(app_key, c);
    });
    s.handle<GetPsdkVersion>([](const GetPsdkVersion&) {
      PsdkVersionAck a;
      a.version = {1, 5, 0, 0};
      return a;
    });
    s.handle<Handshake>([](const Handshake& h) {
      HandshakeAck a;
      a.data = h.data;
      return a;
    });
    s.handle<GetProductInfo>([](const GetProductInfo&) {
      ProductInfoAck a;
      a.product_name = "K40T";
      a.product_id = "k40t";
      a.developer_account = "dev@example.com";
      return a;
    });
    s.handle<GetProductAlias>([](const GetProductAlias&) {
      ProductAliasAck a;
      a.alias = "K40T pod";
      return a;
    });
    s.handle<GetSkyportVersion>([](const GetSkyportVersion&) {
      SkyportVersionAck a;
      a.version = {1, 5, 0, 0};
      return a;
    });
    s.handle<BatteryInfoPush>([this](const BatteryInfoPush& b) {
      count(BatteryInfoPush::kName);
      std::lock_guard<std::mutex> lock(mutex_);
      last_battery_ = b;
      BatteryInfoAck a;
      a.power_off_ready = b.power_off_soon;  // "recording stopped" at once
      return a;
    });
    s.handle<AttitudePush>([this](const AttitudePush&) { count(AttitudePush::kName); });
    s.handle<GpsPush>([this](const GpsPush& g) {
      count(GpsPush::kName);
      std::lock_guard<std::mutex> lock(mutex_);
      last_gps_ = g;
    });
    s.handle<UtcTimePush>([this](const UtcTimePush&) { count(UtcTimePush::kName); });
    if (handle_camera_and_gimbal) add_camera_and_gimbal();
  }

  ~TestPayload() { session_->stop(); }

  static Data code_data(AckCode code) {
    Data d;
    d.bytes[0] = static_cast<uint8_t>(code);
    d.size = 1;
    return d;
  }  // before the state its handlers use goes

  Session& session() { return *session_; }
  uint64_t pushes(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    return counts_[name];
  }
  GpsPush last_gps() {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_gps_;
  }
  BatteryInfoPush last_battery() {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_battery_;
  }

 private:
  void count(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++counts_[name];
  }
  void add_camera_and_gimbal() {
    Session& s = *session_;
    s.handle<GetCameraCapability>([](const GetCameraCapability&) {
      CameraCapabilityAck a;
      a.supported = {true, true, false, true, true};
      return a;
    });
    serve_setting<SetCameraWorkMode, GetCameraWorkMode>(mode_, &SetCameraWorkMode::mode,
                                                        &CameraWorkModeAck::mode);
    s.handle<ShootPhoto>([this](const ShootPhoto&) {
      return mode_ == CameraWorkMode::kShootPhoto ? AckCode::kOk : AckCode::kError;
    });
    s.handle<GetShootPhotoState>([](const GetShootPhotoState&) { return ShootPhotoStateAck{}; });
    // 3.4.5/3.4.6 as DJI's headers lay them out (uint16 interval, docs/psdk.md P30), the
    // simulator's default reading: the set's 5 bytes kept and sent back after the return code.
    s.on_command(SetShootPhotoMode::key(),
                 [this](const IncomingCommand& in) -> std::optional<Data> {
                   if (in.data.size != 5) return code_data(AckCode::kError);
                   lock_and([&] { photo_mode_.assign(in.data.data(), in.data.data() + 5); });
                   return code_data(AckCode::kOk);
                 });
    s.on_command(GetShootPhotoMode::key(), [this](const IncomingCommand&) -> std::optional<Data> {
      Data d = code_data(AckCode::kOk);
      lock_and([&] {
        for (uint8_t b : photo_mode_) d.bytes[d.size++] = b;
      });
      return d;
    });
    s.handle<RecordVideo>([this](const RecordVideo& c) {
      return lock_and([&] { recording_ = c.action == RecordAction::kStart; });
    });
    s.handle<GetRecordState>([this](const GetRecordState&) {
      RecordStateAck a;
      lock_and([&] { a.recording = recording_; });
      return a;
    });
    s.handle<GetSdCardInfo>([](const GetSdCardInfo&) {
      SdCardInfoAck a;
      a.state.inserted = true;
      a.remaining_mb = 1000;
      return a;
    });
    s.handle<GetOpticalZoomSpec>([](const GetOpticalZoomSpec&) {
      OpticalZoomSpecAck a;
      a.min_focal_length_mm = 6.5;
      a.max_focal_length_mm = 317.0;
      a.focal_length_step_mm = 0.1;
      return a;
    });
    serve_setting<SetOpticalZoomFocalLength, GetOpticalZoomFocalLength>(
        focal_mm_, &SetOpticalZoomFocalLength::focal_length_mm,
        &OpticalZoomFocalLengthAck::focal_length_mm);
    s.handle<GetOpticalZoomFactor>(
        [](const GetOpticalZoomFactor&) { return OpticalZoomFactorAck{}; });
    s.handle<StartContinuousZoom>([](const StartContinuousZoom&) { return AckCode::kOk; });
    s.handle<StopContinuousZoom>([](const StopContinuousZoom&) { return AckCode::kOk; });
    serve_setting<SetFocusMode, GetFocusMode>(focus_, &SetFocusMode::mode, &FocusModeAck::mode);
    serve_setting<SetMeteringMode, GetMeteringMode>(metering_, &SetMeteringMode::mode,
                                                    &MeteringModeAck::mode);
    s.handle<GetGimbalCapability>([](const GetGimbalCapability&) {
      GimbalCapabilityAck a;
      a.supported = true;
      return a;
    });
    s.handle<GetGimbalState>([this](const GetGimbalState&) {
      GimbalStateAck a;
      lock_and([&] { a.angles = angles_; });
      return a;
    });
    s.handle<SetGimbalMode>([](const SetGimbalMode&) { return AckCode::kOk; });
    s.handle<ControlGimbalAngle>([this](const ControlGimbalAngle& c) {
      return lock_and([&] { angles_ = {c.pitch_deg, c.roll_deg, c.yaw_deg}; });
    });
    s.handle<ControlGimbalSpeed>([](const ControlGimbalSpeed&) { return AckCode::kOk; });
    s.handle<GimbalReturnHead>(
        [this](const GimbalReturnHead&) { return lock_and([&] { angles_ = {}; }); });
    s.handle<CalibrateGimbal>([](const CalibrateGimbal&) { return AckCode::kOk; });
    s.handle<GetCalibrationProgress>([](const GetCalibrationProgress&) {
      CalibrationProgressAck a;
      a.progress_percent = 100;
      return a;
    });
    s.handle<GetGimbalAdditionalStatus>(
        [](const GetGimbalAdditionalStatus&) { return GimbalAdditionalStatusAck{}; });
  }
  // A setting the payload keeps: Set's field `from` stores it, Get's ACK answers it in `to`.
  template <class Set, class Get, class T, class SetOwner, class AckOwner>
  void serve_setting(T& stored, T SetOwner::*from, T AckOwner::*to) {
    session_->handle<Set>(
        [this, &stored, from](const Set& c) { return lock_and([&] { stored = c.*from; }); });
    session_->handle<Get>([this, &stored, to](const Get&) {
      typename Get::Ack a;
      lock_and([&] { a.*to = stored; });
      return a;
    });
  }
  template <class F>
  AckCode lock_and(F f) {
    std::lock_guard<std::mutex> lock(mutex_);
    f();
    return AckCode::kOk;
  }

  std::unique_ptr<Session> session_;
  std::mutex mutex_;
  std::map<std::string, uint64_t> counts_;
  GpsPush last_gps_;
  BatteryInfoPush last_battery_;
  CameraWorkMode mode_ = CameraWorkMode::kShootPhoto;
  bool recording_ = false;
  double focal_mm_ = 6.5;
  FocusMode focus_ = FocusMode::kManual;
  MeteringMode metering_ = MeteringMode::kAverage;
  GimbalAngles angles_;
  std::vector<uint8_t> photo_mode_;  // the last shoot photo mode set, as sent
};

// Both sides are stopped before either is destroyed: a running side may still be writing into
// its peer's link.
struct Rig {
  Rig() = default;
  Rig(Rig&&) = default;
  ~Rig() {
    if (adapter) adapter->stop();
    if (payload) payload->session().stop();
  }
  std::unique_ptr<TestPayload> payload;
  std::unique_ptr<AdapterSimulator> adapter;
};

inline Rig make_rig(AdapterOptions options, const Credentials& payload_credentials = kCredentials,
                    bool payload_handles_camera = true) {
  auto adapter_link = std::make_unique<FakeLink>();
  auto payload_link = std::make_unique<FakeLink>();
  FakeLink::pair(*adapter_link, *payload_link);
  Rig rig;
  rig.payload = std::make_unique<TestPayload>(std::move(payload_link), payload_credentials,
                                              payload_handles_camera);
  rig.adapter = std::make_unique<AdapterSimulator>(std::move(adapter_link), std::move(options));
  EXPECT_TRUE(rig.payload->session().start());
  EXPECT_TRUE(rig.adapter->start());
  return rig;
}

inline AdapterOptions default_options() {
  AdapterOptions o;
  o.credentials = kCredentials;
  return o;
}

}  // namespace k40t::psdk::sim::testing
