// ThermalMeasurementWatch: whether the pod measures temperatures (and so sends 0x000004, section
// 3.2.2.4), from the frames it accepted and the settings it read back.
#include <gtest/gtest.h>

#include "framed_message.h"
#include "k40t_driver/driver/thermal_measurement_watch.h"
#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::driver {
namespace {

namespace p = protocol;
using k40t::testing::Framed;
using k40t::testing::plain_ack;

constexpr p::MessageId kMeasurement = p::ThermalMeasurementRequest::kId;

TEST(ThermalMeasurementWatch, OnUntilThePodAcceptsOff) {
  ThermalMeasurementWatch watch;
  const p::CodecOptions codec;
  EXPECT_TRUE(watch.measuring()) << "the document's default";
  p::ThermalMeasurementRequest off;
  off.measurement_on = false;
  watch.frame_sent(Framed(off).view, codec);
  EXPECT_TRUE(watch.measuring()) << "not before the pod accepts it";
  watch.frame_received(plain_ack(kMeasurement, p::ResponseCode::kOk).view, codec);
  EXPECT_FALSE(watch.measuring());

  p::ThermalMeasurementRequest on;
  watch.frame_sent(Framed(on).view, codec);
  watch.frame_received(plain_ack(kMeasurement, p::ResponseCode::kFailure).view, codec);
  EXPECT_FALSE(watch.measuring()) << "refused: still off";
}

TEST(ThermalMeasurementWatch, TheReadBackSaysWhatThePodDoes) {
  ThermalMeasurementWatch watch;
  const p::CodecOptions codec;
  p::ThermalSettingsAck settings;
  settings.measurement_on = false;
  watch.frame_received(Framed(settings).view, codec);
  EXPECT_FALSE(watch.measuring());
  settings.measurement_on = true;
  watch.frame_received(Framed(settings).view, codec);
  EXPECT_TRUE(watch.measuring());
}

}  // namespace
}  // namespace k40t::driver
