// LaserTargetRecord (driver/laser_target_record.h): the last laser range for locate_pixel, and the
// distance between the driver's laser target and the pod's (TargetGpsAck, 3.2.4.24) when their
// stamps are at most a second apart; a refused answer is ignored.
#include <gtest/gtest.h>

#include "k40t_driver/driver/laser_target_record.h"

namespace k40t::driver {
namespace {

constexpr StampNs kT0 = 50'000'000'000;
constexpr double kLat = 45.0, kLon = 7.0, kAltitudeMsl = 100.0;

protocol::TargetGpsAck pod_answer(double latitude_deg,
                                  protocol::ResponseCode code = protocol::ResponseCode::kOk) {
  protocol::TargetGpsAck a;
  a.code = code;
  a.latitude_deg = latitude_deg;
  a.longitude_deg = kLon;
  a.altitude_m = kAltitudeMsl;
  return a;
}

// The driver's target at the pod's altitude, on the ellipsoid, 0.001 degree of latitude (111.1 m
// at 45 degrees) south of kLat.
geo::Geodetic local_target() {
  const Result<double> h = geo::Geoid::egm96().ellipsoid_from_msl(kLat, kLon, kAltitudeMsl);
  EXPECT_TRUE(h) << h.error();
  return {kLat - 0.001, kLon, h ? h.value() : 0.0};
}

TEST(LaserTargetRecord, KeepsTheLastRange) {
  LaserTargetRecord record;
  EXPECT_FALSE(record.last_range_m());
  record.range(120.5);
  record.range(80.25);
  EXPECT_EQ(record.last_range_m(), std::optional<double>(80.25));
}

TEST(LaserTargetRecord, ComparesTargetsAtMostASecondApart) {
  for (const StampNs offset : {StampNs{0}, StampNs{999'000'000}, StampNs{-1'000'000'000}}) {
    LaserTargetRecord record;
    record.located(local_target(), kT0);
    EXPECT_FALSE(record.summary().disagreement_m);  // nothing from the pod yet
    record.pod_target(pod_answer(kLat), kT0 + offset);
    const std::optional<double> d = record.summary().disagreement_m;
    ASSERT_TRUE(d) << offset;
    EXPECT_NEAR(*d, 111.1, 0.5) << offset;
  }
}

TEST(LaserTargetRecord, DoesNotCompareTargetsMoreThanASecondApart) {
  LaserTargetRecord record;
  record.pod_target(pod_answer(kLat), kT0);
  record.located(local_target(), kT0 + 1'000'000'001);
  EXPECT_FALSE(record.summary().disagreement_m);
}

TEST(LaserTargetRecord, IgnoresARefusedPodAnswer) {
  LaserTargetRecord record;
  record.located(local_target(), kT0);
  record.pod_target(pod_answer(kLat, protocol::ResponseCode::kFailure), kT0);
  EXPECT_FALSE(record.summary().disagreement_m);
}

TEST(LaserTargetRecord, CountsLocatedTargetsAndKeepsTheLastError) {
  LaserTargetRecord record;
  record.not_located("no fix");
  EXPECT_EQ(record.summary().located, 0u);
  EXPECT_EQ(record.summary().last_error, "no fix");
  record.located(local_target(), kT0);
  record.located(local_target(), kT0 + 1);
  EXPECT_EQ(record.summary().located, 2u);
  EXPECT_EQ(record.summary().last_error, "");
}

}  // namespace
}  // namespace k40t::driver
