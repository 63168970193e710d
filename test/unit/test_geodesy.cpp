// geo/geodesy.h: GeographicLib's WGS 84 conversions and PROJ's EGM96 geoid, checked against
// reference values that do not come from those libraries.
#include <dirent.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "k40t_driver/geo/geodesy.h"

namespace k40t::geo {
namespace {

// WGS 84 defining constants (NIMA TR8350.2, section 3): semi-major axis and flattening.
constexpr double kA = 6378137.0;
constexpr double kF = 1.0 / 298.257223563;
constexpr double kB = kA * (1 - kF);  // semi-minor axis, 6356752.314245 m

TEST(Geodesy, EcefOfTheAxesIsTheEllipsoidsSemiAxes) {
  // On the equator at longitude 0 and 90, and at the pole: the semi-axes, by definition.
  Result<Ecef> equator = to_ecef({0, 0, 0});
  ASSERT_TRUE(equator) << equator.error();
  EXPECT_NEAR(equator->x, kA, 1e-6);
  EXPECT_NEAR(equator->y, 0, 1e-6);
  EXPECT_NEAR(equator->z, 0, 1e-6);
  Result<Ecef> east = to_ecef({0, 90, 100});
  ASSERT_TRUE(east);
  EXPECT_NEAR(east->y, kA + 100, 1e-6);
  Result<Ecef> pole = to_ecef({90, 0, -50});
  ASSERT_TRUE(pole);
  EXPECT_NEAR(pole->z, kB - 50, 1e-6);
  EXPECT_NEAR(pole->x, 0, 1e-6);
}

TEST(Geodesy, EcefAtMidLatitudeFollowsThePrimeVerticalRadius) {
  // x = (N + h) cos(lat) cos(lon), z = (N (1 - e^2) + h) sin(lat), N = a / sqrt(1 - e^2 sin^2).
  const double lat = 45.0 * M_PI / 180, lon = 30.0 * M_PI / 180, h = 1234.5;
  const double e2 = kF * (2 - kF);
  const double n = kA / std::sqrt(1 - e2 * std::sin(lat) * std::sin(lat));
  Result<Ecef> p = to_ecef({45, 30, h});
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x, (n + h) * std::cos(lat) * std::cos(lon), 1e-6);
  EXPECT_NEAR(p->y, (n + h) * std::cos(lat) * std::sin(lon), 1e-6);
  EXPECT_NEAR(p->z, (n * (1 - e2) + h) * std::sin(lat), 1e-6);
  const Geodetic back = from_ecef(p.value());
  EXPECT_NEAR(back.latitude_deg, 45, 1e-11);
  EXPECT_NEAR(back.longitude_deg, 30, 1e-11);
  EXPECT_NEAR(back.height_ellipsoid_m, h, 1e-6);
}

TEST(Geodesy, RefusesImpossibleLatitudesAndNonFiniteInput) {
  EXPECT_FALSE(to_ecef({90.5, 0, 0}));
  EXPECT_FALSE(to_ecef({std::nan(""), 0, 0}));
  EXPECT_FALSE(LocalFrame::at({0, INFINITY, 0}));
  EXPECT_FALSE(Geoid::egm96().undulation_m(-91, 0));
}

TEST(Geodesy, LocalFrameAxesPointEastNorthUp) {
  Result<LocalFrame> frame = LocalFrame::at({22.579, 113.9434, 40});
  ASSERT_TRUE(frame) << frame.error();
  // One metre north: latitude grows by 1 / M (meridian radius of curvature), longitude stays.
  const double lat = 22.579 * M_PI / 180, e2 = kF * (2 - kF);
  const double w = 1 - e2 * std::sin(lat) * std::sin(lat);
  const double meridian = kA * (1 - e2) / std::pow(w, 1.5);
  const double prime = kA / std::sqrt(w);
  const Geodetic north = frame->to_geodetic({0, 1, 0});
  EXPECT_NEAR(north.latitude_deg - 22.579, 180 / M_PI / (meridian + 40), 1e-12);
  EXPECT_NEAR(north.longitude_deg, 113.9434, 1e-12);
  const Geodetic east = frame->to_geodetic({1, 0, 0});
  EXPECT_NEAR(east.longitude_deg - 113.9434, 180 / M_PI / ((prime + 40) * std::cos(lat)), 1e-12);
  EXPECT_NEAR(east.latitude_deg, 22.579, 1e-11);
  const Geodetic up = frame->to_geodetic({0, 0, 10});
  EXPECT_NEAR(up.height_ellipsoid_m, 50, 1e-6);
}

TEST(Geodesy, LocalFrameRoundTripsFarAway) {
  Result<LocalFrame> frame = LocalFrame::at({47.0, 8.0, 500});
  ASSERT_TRUE(frame);
  const Enu far{2500.25, -1800.5, -420.125};  // beyond the laser's reach
  const Enu back = frame->to_enu(frame->to_geodetic(far));
  EXPECT_NEAR(back.east, far.east, 1e-6);
  EXPECT_NEAR(back.north, far.north, 1e-6);
  EXPECT_NEAR(back.up, far.up, 1e-6);
  // The tangent plane drops below the ellipsoid: 3 km away the ellipsoid is ~0.7 m below the
  // plane (d^2 / 2R), which a flat-earth formula ignores.
  const Geodetic three_km = frame->to_geodetic({3000, 0, 0});
  EXPECT_NEAR(three_km.height_ellipsoid_m - 500, 3000.0 * 3000.0 / (2 * 6.389e6), 0.01);
}

// The NGA's EGM96 check values (WW15MGH.GRD's test points, geoid heights from the spherical
// harmonic model). PROJ interpolates the 15' grid bilinearly, which stays within a few
// centimetres of the model (5.6 cm at the worst of these points); 0.1 m here.
struct GeoidCheck {
  double latitude_deg, longitude_deg, undulation_m;
};
TEST(Geodesy, DistanceIsTheStraightLineBetweenTwoPositions) {
  EXPECT_NEAR(distance_m({47.1, 8.5, 500.0}, {47.1, 8.5, 400.0}), 100.0, 1e-6);  // plumb line
  // 0.001 deg of latitude on the equator: the meridian's radius of curvature there is b^2 / a =
  // 6356752.3^2 / 6378137 = 6335439 m (WGS 84), so 6335439 * 0.001 * pi / 180 = 110.574 m.
  EXPECT_NEAR(distance_m({0.0, 10.0, 0.0}, {0.001, 10.0, 0.0}), 110.574, 0.001);
  EXPECT_TRUE(std::isnan(distance_m({91.0, 0.0, 0.0}, {0.0, 0.0, 0.0})));
}

TEST(Geoid, Egm96MatchesTheNgaCheckValues) {
  const GeoidCheck checks[] = {
      {38.6281550, 269.7791550, -31.628}, {-14.6212170, 305.0211140, -2.969},
      {46.8743190, 102.4487290, -43.575}, {-23.6174460, 133.8747120, 15.871},
      {38.6254730, 359.9995000, 50.066},  {-0.4667440, 0.0023000, 17.329},
  };
  for (const GeoidCheck& c : checks) {
    const Result<double> n = Geoid::egm96().undulation_m(c.latitude_deg, c.longitude_deg);
    ASSERT_TRUE(n) << n.error();
    EXPECT_NEAR(n.value(), c.undulation_m, 0.1) << c.latitude_deg << ", " << c.longitude_deg;
  }
}

TEST(Geoid, SeaLevelAndEllipsoidHeightsDifferByTheUndulation) {
  const Geoid& geoid = Geoid::egm96();
  const Result<double> n = geoid.undulation_m(46.8743190, 102.4487290);
  const Result<double> msl = geoid.msl_from_ellipsoid(46.8743190, 102.4487290, 1000);
  const Result<double> h = geoid.ellipsoid_from_msl(46.8743190, 102.4487290, 1000);
  ASSERT_TRUE(n && msl && h);
  EXPECT_NEAR(msl.value(), 1000 + 43.575, 0.1);  // the geoid is 43.6 m below the ellipsoid
  EXPECT_NEAR(h.value(), 1000 - 43.575, 0.1);
  EXPECT_NEAR(msl.value() - 1000, -n.value(), 1e-9);
  EXPECT_NEAR(1000 - h.value(), -n.value(), 1e-9);
}

// How many of this process's open files are PROJ's database proj.db.
int open_proj_databases() {
  int count = 0;
  DIR* fds = opendir("/proc/self/fd");
  if (!fds) return -1;
  while (const dirent* entry = readdir(fds)) {
    char target[4096];
    const std::string link = std::string("/proc/self/fd/") + entry->d_name;
    const ssize_t n = readlink(link.c_str(), target, sizeof target - 1);
    if (n <= 0) continue;
    target[n] = '\0';
    const std::string path(target);
    if (path.size() >= 8 && path.compare(path.size() - 8, 8, "/proj.db") == 0) ++count;
  }
  closedir(fds);
  return count;
}

// PROJ 9.1 opens proj.db (~3 MB of SQLite cache in the driver) on every proj_create unless it
// cannot find it; the geoid's grid needs nothing from it (src/geo/geoid.cpp). Not finding it,
// PROJ says so on stderr even at PJ_LOG_NONE: a normal start of the driver prints nothing. In a
// process of its own (a death test's), so that this is the geoid's first load.
TEST(GeoidDeathTest, LoadsTheGridQuietlyWithoutOpeningProjsDatabase) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const Result<double> n = Geoid::egm96().undulation_m(47.4, 8.5);
        std::exit(n && open_proj_databases() == 0 ? 0 : 1);
      },
      testing::ExitedWithCode(0), "^$");
}

}  // namespace
}  // namespace k40t::geo
