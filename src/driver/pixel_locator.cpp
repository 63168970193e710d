#include "k40t_driver/driver/pixel_locator.h"

#include <cmath>

namespace k40t::driver {

namespace {

Result<PixelLocation> fail(const std::string& why) {
  return Result<PixelLocation>::fail(why);
}

Status check_query(const PixelQuery& query, const CameraView& view) {
  if (!std::isfinite(query.u) || !std::isfinite(query.v))
    return Status::fail("u, v must be finite");
  if (query.u < 0 || query.v < 0 || (view.width > 0 && query.u > view.width) ||
      (view.height > 0 && query.v > view.height))
    return Status::fail("u, v must be inside the " + std::to_string(view.width) + "x" +
                        std::to_string(view.height) + " image");
  return Status::ok();
}

// Whether pixel (u, v) is within the tolerance of where the laser's axis (the laser frame's x)
// appears in the view; false when any frame change or projection fails.
bool on_laser_axis(const PixelQuery& query, const CameraView& view, const FrameRay& frame_ray,
                   const PixelLocatorSetup& setup) {
  const Result<geo::BodyRay> laser = frame_ray(view.frame, setup.laser_frame, {1, 0, 0});
  if (!laser) return false;
  const Result<std::array<double, 2>> spot = camera::project_ray(view.lens, laser->direction);
  return spot &&
         std::hypot((*spot)[0] - query.u, (*spot)[1] - query.v) <= setup.laser_axis_tolerance_px;
}

}  // namespace

Result<PixelLocation> locate_pixel(const PixelQuery& query, const CameraView& view,
                                   const VehicleState& vehicle, std::optional<double> last_range_m,
                                   const FrameRay& frame_ray, const PixelLocatorSetup& setup) {
  if (const Status checked = check_query(query, view); !checked) return fail(checked.message());
  // Undistorted normalised coordinates of the pixel (OpenCV, with the lens's D).
  const Result<std::array<double, 2>> normalised =
      camera::pixel_to_normalised(view.lens, query.u, query.v);
  if (!normalised) return fail(normalised.error());
  if (query.plane_reference != 0 && query.plane_reference != 1)
    return fail("plane_reference must be 0 (ABOVE_TAKEOFF) or 1 (MSL)");
  if (!std::isfinite(query.plane_height)) return fail("plane_height must be finite");

  const Result<geo::VehiclePose> pose = vehicle_pose(vehicle);
  if (!pose) return fail(pose.error());
  PixelLocation out;
  out.optical = {(*normalised)[0], (*normalised)[1], 1.0};
  const Result<geo::BodyRay> ray = frame_ray(setup.vehicle_frame, view.frame, out.optical);
  if (!ray) return fail(ray.error());

  out.on_laser_axis =
      query.use_laser && last_range_m && on_laser_axis(query, view, frame_ray, setup);
  Result<geo::Located> located = Result<geo::Located>::fail("not located");
  if (out.on_laser_axis) {
    located = geo::locate_at_range(pose.value(), ray.value(), *last_range_m, setup.uncertainty);
    if (!located) return fail(located.error());
  } else {
    const Result<double> plane_h = plane_height_ellipsoid(
        vehicle,
        query.plane_reference == 0 ? PlaneReference::kAboveTakeoff : PlaneReference::kMeanSeaLevel,
        query.plane_height);
    if (!plane_h) return fail(plane_h.error());
    located = geo::locate_on_plane(pose.value(), ray.value(), plane_h.value() - vehicle.altitude_m,
                                   setup.uncertainty);
    if (!located)
      return fail("the pixel's ray misses the ground plane (above the horizon or beyond 10 km)");
  }
  out.located = located.value();
  const Result<double> msl = geo::Geoid::egm96().msl_from_ellipsoid(
      out.located.position.latitude_deg, out.located.position.longitude_deg,
      out.located.position.height_ellipsoid_m);
  if (msl) out.altitude_msl = msl.value();
  return out;
}

}  // namespace k40t::driver
