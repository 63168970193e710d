// The simulated SKYPORT adapter against a minimal payload built on psdk::Session (the role the
// SKYPORT bridge plays with the real pod behind it): identity verification with the right and a
// wrong key, pushes arriving with consistent values, battery power-off handshake, scripted camera
// and gimbal checks, unsupported commands, get-position, and the faults showing up as counters.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "psdk_adapter_sim_rig.h"

namespace k40t::psdk::sim {
namespace {

using testing::default_options;
using testing::eventually;
using testing::kCredentials;
using testing::make_rig;
using testing::Rig;
using testing::TestPayload;

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

// Once the attitude pushes flow, starts `fault` and expects no push for `quiet` (after 50 ms for
// the frames already in flight); returns the count the pushes stopped at.
template <class Fault>
uint64_t expect_pushes_stop(Rig& rig, Fault fault, std::chrono::milliseconds quiet) {
  EXPECT_TRUE(eventually([&] { return rig.payload->pushes(AttitudePush::kName) > 0; }));
  fault();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const uint64_t before = rig.payload->pushes(AttitudePush::kName);
  std::this_thread::sleep_for(quiet);
  EXPECT_EQ(rig.payload->pushes(AttitudePush::kName), before);
  return before;
}

TEST(PsdkAdapterSim, SilenceStopsThePushes) {
  Rig rig = make_rig(default_options());
  expect_pushes_stop(
      rig, [&] { rig.adapter->silence_for(std::chrono::hours(1)); },
      std::chrono::milliseconds(200));
  EXPECT_GT(rig.adapter->stats().byte_faults.writes_silenced, 0u);
}

}  // namespace
}  // namespace k40t::psdk::sim

namespace k40t::psdk::sim {
namespace {

TEST(PsdkAdapterSim, DisconnectStopsThePushesUntilTheLinkIsBack) {
  Rig rig = make_rig(default_options());
  const uint64_t before = expect_pushes_stop(
      rig, [&] { rig.adapter->disconnect_for(std::chrono::seconds(1)); },
      std::chrono::milliseconds(100));
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
