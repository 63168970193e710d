#include "k40t_driver/sim/ground_truth.h"

#include <sstream>

namespace k40t::sim {

namespace {
constexpr size_t kMaxGeotags = 1000;  // a long run keeps the latest
}

GroundTruth::GroundTruth(const VehicleConfig& config)
    : config_(config), motion_(config.velocity_north_m_s, config.velocity_east_m_s) {
  const Result<double> ground = geo::Geoid::egm96().ellipsoid_from_msl(
      config.origin_latitude_deg, config.origin_longitude_deg, config.origin_ground_msl_m);
  if (!ground) return;
  Result<geo::LocalFrame> frame = geo::LocalFrame::at(
      {config.origin_latitude_deg, config.origin_longitude_deg, ground.value()});
  if (frame) frame_ = frame.value();
}

Vec3 GroundTruth::pod_position(double t_s, double height_m) const {
  const Vec3 ground = motion_.position(t_s);
  return {ground.x, ground.y, height_m};
}

Result<TruePoint> GroundTruth::to_earth(const Vec3& point) const {
  if (!frame_) return Result<TruePoint>::fail("no geoid: ground truth unavailable");
  TruePoint out;
  out.geodetic = frame_->to_geodetic({point.y, point.x, point.z});
  const Result<double> msl = geo::Geoid::egm96().msl_from_ellipsoid(
      out.geodetic.latitude_deg, out.geodetic.longitude_deg, out.geodetic.height_ellipsoid_m);
  if (!msl) return Result<TruePoint>::fail(msl.error());
  out.msl_m = msl.value();
  return out;
}

Result<Vec3> GroundTruth::from_earth(double latitude_deg, double longitude_deg,
                                     double msl_m) const {
  if (!frame_) return Result<Vec3>::fail("no geoid: ground truth unavailable");
  const Result<double> h =
      geo::Geoid::egm96().ellipsoid_from_msl(latitude_deg, longitude_deg, msl_m);
  if (!h) return Result<Vec3>::fail(h.error());
  const geo::Enu enu = frame_->to_enu({latitude_deg, longitude_deg, h.value()});
  return Vec3{enu.north, enu.east, enu.up};
}

void GroundTruth::photo_taken(uint64_t photo_id, const Vec3& pod) {
  if (geotags_.size() >= kMaxGeotags) geotags_.erase(geotags_.begin());
  GeotagRecord record;
  record.photo_id = photo_id;
  record.at_photo = pod;
  geotags_.push_back(record);
}

void GroundTruth::photo_answered(uint64_t photo_id, const Vec3& pod, double latitude_deg,
                                 double longitude_deg, double msl_m) {
  for (GeotagRecord& record : geotags_) {
    if (record.photo_id != photo_id) continue;
    record.at_answer = pod;
    record.answer = TruePoint{{latitude_deg, longitude_deg, 0}, msl_m};
  }
}

std::string GroundTruth::describe_geotags() const {
  std::ostringstream out;
  size_t answered = 0;
  for (const GeotagRecord& r : geotags_) answered += r.answer ? 1 : 0;
  out << geotags_.size() << " photos, " << answered << " answered";
  for (const GeotagRecord& r : geotags_) {
    if (!r.answer || !r.at_answer) continue;
    const Result<Vec3> answer = from_earth(r.answer->geodetic.latitude_deg,
                                           r.answer->geodetic.longitude_deg, r.answer->msl_m);
    if (!answer) continue;
    out << "; photo " << r.photo_id << " error_m " << norm(answer.value() - r.at_photo)
        << " moved_m " << norm(*r.at_answer - r.at_photo);
  }
  return out.str();
}

void GroundTruth::flight_data_received(ReceivedFlightData data) {
  data.requests = received_.requests + 1;
  received_ = data;
}

}  // namespace k40t::sim
