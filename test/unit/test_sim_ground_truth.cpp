// sim/ground_truth.h and the moving vehicle: the pod moves, the world's objects stay where they
// are on the Earth, the geotag log measures answers against the truth, and the flight data of the
// host's last 0x000320 is kept for the control socket.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geo_test_support.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/sim/control_commands.h"
#include "k40t_driver/sim/pod_model.h"
#include "sim_control_target.h"
#include "sim_pod_harness.h"

namespace k40t::sim {
namespace {

PodConfig moving_east(double speed) {
  PodConfig config;
  config.vehicle.velocity_east_m_s = speed;
  return config;
}

TEST(SimGroundTruth, ThePodMovesAndTheObjectsStay) {
  PodModel pod(moving_east(15));
  const Vec3 hot_before = pod.hot_object_position();
  const Vec3 relative_before = pod.world().hot_object_centre();
  for (int i = 0; i < 200; ++i) pod.step(0.01);  // 2 s
  const Vec3 at = pod.pod_position();
  EXPECT_NEAR(at.x, 0, 1e-9);
  EXPECT_NEAR(at.y, 30, 1e-9);
  EXPECT_NEAR(at.z, pod.world().config().ground_height_m, 1e-9);
  const Vec3 hot_after = pod.hot_object_position();
  EXPECT_NEAR(norm(hot_after - hot_before), 0, 1e-9);
  // Seen from the pod, the object moved 30 m west.
  EXPECT_NEAR(pod.world().hot_object_centre().y, relative_before.y - 30, 1e-9);
  // The hot object stands on the ground: its centre one radius up.
  EXPECT_NEAR(hot_after.z, pod.world().config().hot.radius_m, 1e-9);
}

TEST(SimGroundTruth, TheLaserSpotIsOnTheGroundBelow) {
  PodModel pod(moving_east(10));
  pod.gimbal().look_down();
  for (int i = 0; i < 500; ++i) pod.step(0.01);
  const std::optional<Vec3> spot = pod.laser_spot();
  ASSERT_TRUE(spot);
  EXPECT_NEAR(spot->z, 0, 1e-6);
  EXPECT_NEAR(spot->y, pod.pod_position().y, 1e-6);
}

TEST(SimGroundTruth, EarthPositionsOfTheTruthFrame) {
  const GroundTruth truth;
  const VehicleConfig& c = truth.config();
  const Result<TruePoint> origin = truth.to_earth({0, 0, 0});
  ASSERT_TRUE(origin) << origin.error();
  EXPECT_NEAR(origin->geodetic.latitude_deg, c.origin_latitude_deg, 1e-12);
  EXPECT_NEAR(origin->msl_m, c.origin_ground_msl_m, 1e-6);
  const Result<TruePoint> north = truth.to_earth({100, 0, 30});
  ASSERT_TRUE(north);
  EXPECT_NEAR(test::metres_north(c.origin_latitude_deg, north->geodetic.latitude_deg,
                                 c.origin_ground_msl_m),
              100, 1e-2);
  const Result<Vec3> back =
      truth.from_earth(north->geodetic.latitude_deg, north->geodetic.longitude_deg, north->msl_m);
  ASSERT_TRUE(back);
  EXPECT_NEAR(norm(back.value() - Vec3{100, 0, 30}), 0, 1e-6);
}

TEST(SimGroundTruth, GeotagLogMeasuresAnswersAgainstThePhotoTime) {
  GroundTruth truth;
  const Result<TruePoint> three_m_east = truth.to_earth({0, 3, 30});
  ASSERT_TRUE(three_m_east);
  truth.photo_taken(7, {0, 0, 30});
  truth.photo_taken(8, {0, 10, 30});  // never answered
  truth.photo_answered(7, {0, 4, 30}, three_m_east->geodetic.latitude_deg,
                       three_m_east->geodetic.longitude_deg, three_m_east->msl_m);
  const std::string text = truth.describe_geotags();
  EXPECT_NE(text.find("2 photos, 1 answered"), std::string::npos) << text;
  EXPECT_NE(text.find("photo 7 error_m 3"), std::string::npos) << text;
  EXPECT_NE(text.find("moved_m 4"), std::string::npos) << text;
  EXPECT_EQ(text.find("photo 8"), std::string::npos) << text;
}

TEST(SimGroundTruth, TheFlightDataOfTheLastTargetRequestIsKept) {
  testing::PodHarness harness;
  EXPECT_EQ(harness.pod.ground_truth().received_flight_data().requests, 0u);
  protocol::TargetGpsRequest request;
  request.latitude_deg = 47.3769;
  request.longitude_deg = 8.5417;
  request.ground_speed_m_s = 12.34;
  request.climb_rate_m_s = -1.5;
  request.heading_deg = 271.5;
  request.airspeed_m_s = 13.0;
  request.throttle_percent = 40.0;
  harness.send(request);  // no laser return at the start: zeros, but received
  request.ground_speed_m_s = 7.25;
  harness.send(request);
  const ReceivedFlightData& got = harness.pod.ground_truth().received_flight_data();
  EXPECT_EQ(got.requests, 2u);
  EXPECT_NEAR(got.ground_speed_m_s, 7.25, 1e-9);  // the last one's, through the wire's 0.01 m/s
  EXPECT_NEAR(got.climb_rate_m_s, -1.5, 1e-9);
  EXPECT_NEAR(got.heading_deg, 271.5, 1e-9);
  EXPECT_NEAR(got.airspeed_m_s, 13.0, 1e-9);
  EXPECT_NEAR(got.throttle_percent, 40.0, 1e-9);

  testing::FakeTarget target;
  target.pod.ground_truth().flight_data_received(got);
  EXPECT_EQ(execute_control_command("flight-data", target),
            "ok requests 1 ground_speed 7.25 climb -1.5 heading 271.5 airspeed 13 throttle 40");
}

}  // namespace
}  // namespace k40t::sim
