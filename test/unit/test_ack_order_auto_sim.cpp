// `ack_byte_order: auto` end to end (docs/protocol/decisions.md#conventions): the simulator plays a
// byte order for its ACKs, the driver core starts on auto, locks onto the pod's order with the
// first ACK that tells (here the thermal settings read-back) and from then on reads every ACK,
// response code and settings read-back in it, and answers the pod's GPS request 0x000310 in it.
#include <gtest/gtest.h>

#include <optional>

#include "conventions_rig.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::driver::testing {
namespace {

namespace p = protocol;
using test::eventually;

auto pod_with_order(p::ByteOrder order) {
  return [order](sim::SimOptions& o) { o.codec.ack_byte_order = order; };
}

p::ThermalSettingsAck pod_settings(ConventionsRig& rig) {
  p::ThermalSettingsAck reported;
  rig.pod().with_model([&](sim::PodModel& m) { reported = m.thermal().settings().reported; });
  return reported;
}

// The read-back's 16-bit fields are what only the right byte order reads back right.
void expect_read_back_equals_the_pods(ConventionsRig& rig) {
  Result<p::ThermalSettingsAck> read = rig.driver().request_typed(p::ThermalReadSettingsRequest{});
  ASSERT_TRUE(read) << read.error();
  const p::ThermalSettingsAck truth = pod_settings(rig);
  EXPECT_EQ(read->high_alarm_on, truth.high_alarm_on);
  EXPECT_EQ(read->low_alarm_on, truth.low_alarm_on);
  EXPECT_EQ(read->difference_alarm_on, truth.difference_alarm_on);
  EXPECT_DOUBLE_EQ(read->threshold_reference_degC, truth.threshold_reference_degC);
  EXPECT_DOUBLE_EQ(read->threshold_float_degC, truth.threshold_float_degC);
  EXPECT_EQ(read->sharpness, truth.sharpness);
  EXPECT_EQ(read->denoise_level, truth.denoise_level);
}

TEST(AckOrderAuto, ALittleEndianPodIsDetectedAndReadRight) {
  ConventionsRig rig({}, {"ack_byte_order=auto"}, pod_with_order(p::ByteOrder::kLittle));
  EXPECT_EQ(rig.reading("ack_byte_order").value, "auto");
  expect_read_back_equals_the_pods(rig);
  EXPECT_EQ(rig.driver().codec().ack_byte_order, p::ByteOrder::kLittle);
  EXPECT_FALSE(rig.driver().codec().ack_byte_order_auto);
  EXPECT_TRUE(eventually([&] { return rig.reading("ack_byte_order").value == "little"; }));
  const ConventionStatus status = rig.reading("ack_byte_order");
  EXPECT_EQ(status.source.rfind("auto: detected little from ACK 0x010100 bytes ", 0), 0u)
      << status.source;
  EXPECT_EQ(status.contradiction, "");
  // A later read-back still reads right, and agrees.
  expect_read_back_equals_the_pods(rig);
  EXPECT_EQ(rig.reading("ack_byte_order").contradiction, "");
}

// After the lock a refusal's response code reads right: "no SD card" (section 3.3, 0x0204), sent
// 04 02 by this pod, would read 0x0402 big-endian, no code of the list.
TEST(AckOrderAuto, ARefusalAfterTheLockReadsItsCode) {
  ConventionsRig rig({}, {"ack_byte_order=auto"}, pod_with_order(p::ByteOrder::kLittle));
  ASSERT_TRUE(rig.driver().request_typed(p::ThermalReadSettingsRequest{}));
  rig.pod().with_model([](sim::PodModel& m) { m.camera().sd().remove(); });
  p::TakePhotoRequest photo;
  photo.lens = p::PhotoLensMode::kVisible;
  const session::AckResult refused = rig.driver().request(photo);
  EXPECT_TRUE(refused.received);
  EXPECT_EQ(refused.code, p::ResponseCode::kNoSdCard) << refused.message;
}

// Without auto the same pod's read-back is refused or misread (the test above can fail).
TEST(AckOrderAuto, TheDefaultMisreadsALittleEndianPod) {
  ConventionsRig rig({}, {}, pod_with_order(p::ByteOrder::kLittle));
  Result<p::ThermalSettingsAck> read = rig.driver().request_typed(p::ThermalReadSettingsRequest{});
  const p::ThermalSettingsAck truth = pod_settings(rig);
  EXPECT_TRUE(!read || read->threshold_float_degC != truth.threshold_float_degC);
  EXPECT_EQ(rig.driver().codec().ack_byte_order, p::ByteOrder::kBig);
}

TEST(AckOrderAuto, ABigEndianPodStaysBig) {
  ConventionsRig rig({}, {"ack_byte_order=auto"}, pod_with_order(p::ByteOrder::kBig));
  expect_read_back_equals_the_pods(rig);
  EXPECT_TRUE(eventually([&] { return rig.reading("ack_byte_order").value == "big"; }));
  EXPECT_EQ(rig.reading("ack_byte_order").source.rfind("auto: detected big from ACK 0x010100", 0),
            0u)
      << rig.reading("ack_byte_order").source;
  EXPECT_EQ(rig.driver().codec().ack_byte_order, p::ByteOrder::kBig);
}

// After the lock, the driver's answer to the pod's GPS request (0x010310: response code in
// ack_byte_order, data too under gps_answer_byte_order: ack) is in the pod's order: the simulator
// reads the position the driver was given.
TEST(AckOrderAuto, TheGpsAnswerFollowsTheDetectedOrder) {
  ConventionsRig rig({}, {"ack_byte_order=auto"}, pod_with_order(p::ByteOrder::kLittle));
  ASSERT_TRUE(rig.driver().request_typed(p::ThermalReadSettingsRequest{}));
  VehicleState vehicle;
  vehicle.has_fix = true;
  vehicle.gps_status = 3;
  vehicle.latitude_deg = 47.3977;
  vehicle.longitude_deg = 8.5456;
  vehicle.altitude_msl_m = 488.2;
  vehicle.relative_altitude_m = 12.5;
  rig.driver().set_vehicle_state(vehicle);
  p::TakePhotoRequest photo;
  photo.lens = p::PhotoLensMode::kVisible;
  ASSERT_TRUE(rig.driver().request(photo).ok());
  std::optional<sim::PhotoRecord> taken;
  ASSERT_TRUE(eventually([&] {
    rig.pod().with_model([&](sim::PodModel& pod) {
      if (!pod.camera().photos().empty() && pod.camera().photos()[0].gps)
        taken = pod.camera().photos()[0];
    });
    return taken.has_value();
  })) << "the simulator never read a GPS answer";
  EXPECT_NEAR(taken->gps->position.latitude_deg, 47.3977, 1e-6);
  EXPECT_NEAR(taken->gps->position.longitude_deg, 8.5456, 1e-6);
  EXPECT_NEAR(taken->gps->position.altitude_m, 488.2, 0.1);
}

}  // namespace
}  // namespace k40t::driver::testing
