// The simulated SKYPORT adapter against a minimal payload built on psdk::Session (the role the
// SKYPORT bridge plays with the real pod behind it): identity verification with the right and a
// wrong key, pushes arriving with consistent values, battery power-off handshake, scripted camera
// and gimbal checks, unsupported commands, get-position, and the faults showing up as counters.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "k40t_driver/psdk/identity.h"
#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "psdk_fake_transport.h"

namespace k40t::psdk::sim {
namespace {

using testing::FakeLink;

const Credentials kCredentials = {"K40T bridge", "123456", "0123456789abcdef0123456789abcdef",
                                  "dev@example.com"};

bool eventually(const std::function<bool()>& condition,
                std::chrono::seconds deadline = std::chrono::seconds(15)) {
  const auto until = std::chrono::steady_clock::now() + deadline;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

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
    s.handle<SetCameraWorkMode>(
        [this](const SetCameraWorkMode& c) { return lock_and([&] { mode_ = c.mode; }); });
    s.handle<GetCameraWorkMode>([this](const GetCameraWorkMode&) {
      CameraWorkModeAck a;
      lock_and([&] { a.mode = mode_; });
      return a;
    });
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
    s.handle<SetOpticalZoomFocalLength>([this](const SetOpticalZoomFocalLength& c) {
      return lock_and([&] { focal_mm_ = c.focal_length_mm; });
    });
    s.handle<GetOpticalZoomFocalLength>([this](const GetOpticalZoomFocalLength&) {
      OpticalZoomFocalLengthAck a;
      lock_and([&] { a.focal_length_mm = focal_mm_; });
      return a;
    });
    s.handle<GetOpticalZoomFactor>(
        [](const GetOpticalZoomFactor&) { return OpticalZoomFactorAck{}; });
    s.handle<StartContinuousZoom>([](const StartContinuousZoom&) { return AckCode::kOk; });
    s.handle<StopContinuousZoom>([](const StopContinuousZoom&) { return AckCode::kOk; });
    s.handle<SetFocusMode>(
        [this](const SetFocusMode& c) { return lock_and([&] { focus_ = c.mode; }); });
    s.handle<GetFocusMode>([this](const GetFocusMode&) {
      FocusModeAck a;
      lock_and([&] { a.mode = focus_; });
      return a;
    });
    s.handle<SetMeteringMode>(
        [this](const SetMeteringMode& c) { return lock_and([&] { metering_ = c.mode; }); });
    s.handle<GetMeteringMode>([this](const GetMeteringMode&) {
      MeteringModeAck a;
      lock_and([&] { a.mode = metering_; });
      return a;
    });
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

Rig make_rig(AdapterOptions options, const Credentials& payload_credentials = kCredentials,
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

AdapterOptions default_options() {
  AdapterOptions o;
  o.credentials = kCredentials;
  return o;
}

TEST(PsdkAdapterSim, IdentityPassesWithTheRightKey) {
  Rig rig = make_rig(default_options());
  EXPECT_TRUE(eventually([&] { return rig.adapter->stats().identity_passed >= 1; }));
  const IdentityResult r = rig.adapter->verify_identity();
  EXPECT_TRUE(r.answered);
  EXPECT_TRUE(r.passed) << r.detail;
  EXPECT_EQ(rig.adapter->stats().identity_failed, 0u);
}

TEST(PsdkAdapterSim, IdentityFailsWithAWrongKey) {
  Credentials wrong = kCredentials;
  wrong.app_key = "ffffffffffffffffffffffffffffffff";
  AdapterOptions o = default_options();
  o.encryption = false;  // the AES keys differ too; keep the exchange readable
  Rig rig = make_rig(o, wrong);
  const IdentityResult r = rig.adapter->verify_identity();
  EXPECT_TRUE(r.answered);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.detail.find("does not match"), std::string::npos) << r.detail;
  EXPECT_TRUE(eventually([&] { return rig.adapter->stats().identity_failed >= 2; }));
  EXPECT_EQ(rig.adapter->stats().identity_passed, 0u);
}

TEST(PsdkAdapterSim, PushesArriveWithConsistentValues) {
  Rig rig = make_rig(default_options());
  EXPECT_TRUE(eventually([&] {
    return rig.payload->pushes(AttitudePush::kName) >= 50 &&
           rig.payload->pushes(GpsPush::kName) >= 5 &&
           rig.payload->pushes(BatteryInfoPush::kName) >= 1 &&
           rig.payload->pushes(UtcTimePush::kName) >= 1;
  }));
  const GpsPush gps = rig.payload->last_gps();
  const FlightModelOptions home;
  EXPECT_NEAR(gps.latitude_rad * 180.0 / M_PI, home.home_latitude_deg, 0.01);
  EXPECT_NEAR(gps.longitude_rad * 180.0 / M_PI, home.home_longitude_deg, 0.01);
  // Attitude is the fastest push (50 Hz against 5 Hz for GPS).
  EXPECT_GT(rig.payload->pushes(AttitudePush::kName), rig.payload->pushes(GpsPush::kName));
  const AdapterStats stats = rig.adapter->stats();
  EXPECT_GE(stats.battery_acks, 1u);
  EXPECT_FALSE(stats.last_power_off_ready);
  EXPECT_EQ(rig.payload->session().stats().parser.frame_crc_errors, 0u);
  EXPECT_EQ(rig.payload->session().stats().decrypt_errors, 0u);
}

TEST(PsdkAdapterSim, PowerOffIsAnnouncedAndAcknowledgedReady) {
  Rig rig = make_rig(default_options());
  rig.adapter->announce_power_off();
  EXPECT_TRUE(eventually([&] { return rig.adapter->stats().last_power_off_ready; }));
  EXPECT_TRUE(rig.payload->last_battery().power_off_soon);
}

TEST(PsdkAdapterSim, ScriptedChecksPassAgainstAConformingPayload) {
  Rig rig = make_rig(default_options());
  const CheckReport state = rig.adapter->check_payload_state();
  EXPECT_TRUE(state.passed()) << state.summary();
  const CheckReport camera = rig.adapter->check_camera();
  EXPECT_TRUE(camera.passed()) << camera.summary();
  EXPECT_GE(camera.items.size(), 20u);
  const CheckReport gimbal = rig.adapter->check_gimbal();
  EXPECT_TRUE(gimbal.passed()) << gimbal.summary();
  const CheckReport unsupported = rig.adapter->check_unsupported();
  EXPECT_TRUE(unsupported.passed()) << unsupported.summary();
}

TEST(PsdkAdapterSim, ScriptedChecksFailAgainstAPayloadWithoutCamera) {
  Rig rig = make_rig(default_options(), kCredentials, false);
  const CheckReport camera = rig.adapter->check_camera();
  EXPECT_FALSE(camera.passed());
  EXPECT_EQ(camera.failures(), camera.items.size());
  EXPECT_NE(camera.summary().find("command not supported"), std::string::npos) << camera.summary();
}

TEST(PsdkAdapterSim, AnswersGetPositionFromTheFlight) {
  Rig rig = make_rig(default_options());
  GetPosition request;
  request.count = 2;
  request.task_index = 4;
  request.base_time = utc_from_unix_us(FlightModelOptions{}.start_utc_us).date_time;
  request.points[0] = {{1, 0}, 0};
  request.points[1] = {{2, 1}, 2000000};
  AckResult raw;
  const Result<GetPositionAck> ack = rig.payload->session().request(request, &raw);
  ASSERT_TRUE(ack) << ack.error();
  EXPECT_EQ(ack->code, AckCode::kOk);
  ASSERT_EQ(ack->count, 2);
  EXPECT_EQ(ack->task_index, 4);
  EXPECT_EQ(ack->points[1].event.event_index, 2);
  EXPECT_NEAR(ack->points[0].latitude_deg, FlightModelOptions{}.home_latitude_deg, 1e-9);
  // At t = 2 s the airframe is climbing: 6 m above home.
  EXPECT_NEAR(ack->points[1].height_m, FlightModelOptions{}.home_altitude_msl_m + 6.0, 1e-6);
  EXPECT_EQ(rig.adapter->stats().positions_answered, 1u);
}

TEST(PsdkAdapterSim, RecordsFloatingWindowMessages) {
  Rig rig = make_rig(default_options());
  FloatingWindowMessage m;
  m.text = "recording started";
  ASSERT_TRUE(rig.payload->session().send(m));  // encrypted: the payload has the key
  EXPECT_TRUE(eventually([&] { return !rig.adapter->floating_window_messages().empty(); }));
  EXPECT_EQ(rig.adapter->floating_window_messages().front(), "recording started");
}

TEST(PsdkAdapterSim, ByteFaultsShowUpInThePayloadsCounters) {
  AdapterOptions o = default_options();
  o.byte_faults.corrupt_rate = 0.01;
  o.byte_faults.garbage_rate = 0.2;
  Rig rig = make_rig(o);
  EXPECT_TRUE(eventually([&] {
    const ParserStats p = rig.payload->session().stats().parser;
    return p.header_crc_errors + p.frame_crc_errors > 0 && p.bytes_discarded > 0 &&
           p.frames_good > 20;
  }));
  EXPECT_GT(rig.adapter->stats().byte_faults.bytes_corrupted, 0u);
}

TEST(PsdkAdapterSim, DroppedAcksTimeOutAndSequenceJumpsAreCounted) {
  AdapterOptions o = default_options();
  o.protocol_faults.drop_ack_rate = 1.0;
  o.protocol_faults.sequence_jump_rate = 0.5;
  Rig rig = make_rig(o);
  GetPosition request;
  request.base_time = utc_from_unix_us(FlightModelOptions{}.start_utc_us).date_time;
  const Result<GetPositionAck> ack = rig.payload->session().request(request);
  EXPECT_FALSE(ack);
  EXPECT_EQ(rig.adapter->stats().acks_dropped, 1u);
  EXPECT_TRUE(eventually([&] { return rig.payload->session().stats().parser.sequence_gaps > 0; }));
  EXPECT_GT(rig.adapter->stats().sequence_jumps, 0u);
}

TEST(PsdkAdapterSim, DelayedAcksStillArrive) {
  AdapterOptions o = default_options();
  o.protocol_faults.delay_ack_ms = 100;
  Rig rig = make_rig(o);
  GetPosition request;
  request.base_time = utc_from_unix_us(FlightModelOptions{}.start_utc_us).date_time;
  const Result<GetPositionAck> ack = rig.payload->session().request(request);
  ASSERT_TRUE(ack) << ack.error();
  EXPECT_EQ(rig.adapter->stats().acks_delayed, 1u);
}

TEST(PsdkAdapterSim, SilenceStopsThePushes) {
  Rig rig = make_rig(default_options());
  EXPECT_TRUE(eventually([&] { return rig.payload->pushes(AttitudePush::kName) > 0; }));
  rig.adapter->silence_for(std::chrono::hours(1));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // let frames in flight land
  const uint64_t before = rig.payload->pushes(AttitudePush::kName);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(rig.payload->pushes(AttitudePush::kName), before);
  EXPECT_GT(rig.adapter->stats().byte_faults.writes_silenced, 0u);
}

}  // namespace
}  // namespace k40t::psdk::sim

namespace k40t::psdk::sim {
namespace {

TEST(PsdkAdapterSim, DisconnectStopsThePushesUntilTheLinkIsBack) {
  Rig rig = make_rig(default_options());
  EXPECT_TRUE(eventually([&] { return rig.payload->pushes(AttitudePush::kName) > 0; }));
  rig.adapter->disconnect_for(std::chrono::seconds(1));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // let frames in flight land
  const uint64_t before = rig.payload->pushes(AttitudePush::kName);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(rig.payload->pushes(AttitudePush::kName), before);
  EXPECT_TRUE(eventually([&] { return rig.payload->pushes(AttitudePush::kName) > before + 10; }));
  const AdapterStats stats = rig.adapter->stats();
  EXPECT_EQ(stats.byte_faults.disconnects, 1u);
  EXPECT_GT(stats.session.send_errors, 0u);  // pushes while the link was down
}

TEST(PsdkAdapterSim, SequenceJumpOnDemandIsOneGap) {
  AdapterOptions o = default_options();
  o.rates = PushRates{};
  o.rates.attitude_hz = 50;  // one push stream keeps the count simple
  o.rates.gps_hz = o.rates.raw_gps_hz = o.rates.raw_rtk_hz = o.rates.barometric_altitude_hz = 0;
  o.rates.battery_hz = o.rates.uav_state_hz = o.rates.link_bandwidth_hz = 0;
  o.rates.app_date_time_hz = o.rates.utc_time_hz = o.rates.other_payload_hz = 0;
  Rig rig = make_rig(o);
  EXPECT_TRUE(eventually([&] { return rig.payload->pushes(AttitudePush::kName) > 5; }));
  const uint64_t gaps = rig.payload->session().stats().parser.sequence_gaps;
  rig.adapter->jump_sequence(40);
  EXPECT_TRUE(
      eventually([&] { return rig.payload->session().stats().parser.sequence_gaps == gaps + 1; }));
  EXPECT_GE(rig.payload->session().stats().parser.commands_lost, 40u);
}

}  // namespace
}  // namespace k40t::psdk::sim
