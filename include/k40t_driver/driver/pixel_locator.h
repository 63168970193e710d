// locate_pixel's rule, without ROS (docs/geo.md "The driver's own geolocation"): a pixel of a
// view to a position on the Earth. The pixel's ray (undistorted by the view's lens) is taken to
// the vehicle frame, then ended at the last laser range when the pixel is within a tolerance of
// where the laser's axis appears in the image, or else on a horizontal plane at the asked height.
// Every way it can fail is a Result error the service returns as its message.
//
// The ROS glue (ros/target_locator) supplies the view from a CameraInfo and the frame changes
// from TF; a test supplies a fixed mounting.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "k40t_driver/camera/pixel_ray.h"
#include "k40t_driver/driver/vehicle_geo.h"
#include "k40t_driver/driver/vehicle_state.h"
#include "k40t_driver/geo/ray_locator.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::driver {

// One image (or split-screen panel) and its lens.
struct CameraView {
  camera::CameraModel lens;
  uint32_t width = 0;  // 0: unknown, no bound checked
  uint32_t height = 0;
  std::string frame;  // the optical frame: z forward, x right, y down
};

// A direction given in `source_frame` as a ray in `target_frame` (origin and direction), at the
// view's time: TF in ROS.
using FrameRay = std::function<Result<geo::BodyRay>(const std::string& target_frame,
                                                    const std::string& source_frame,
                                                    const geo::Vector3& direction)>;

struct PixelQuery {
  double u = 0, v = 0;      // pixel, (0, 0) the top left corner
  int plane_reference = 0;  // 0 above the take-off point, 1 above mean sea level
  double plane_height = 0;  // m
  bool use_laser = true;    // end on the laser range when the pixel is on its axis
};

struct PixelLocatorSetup {
  std::string vehicle_frame;
  std::string laser_frame;  // its x axis is the laser's
  geo::RayUncertainty uncertainty;
  double laser_axis_tolerance_px = 8;
};

struct PixelLocation {
  geo::Located located;
  std::optional<double> altitude_msl;  // none where the geoid grid has no value
  bool on_laser_axis = false;
  geo::Vector3 optical{0, 0, 1};  // the pixel's ray in the optical frame (x, y, 1)
};

Result<PixelLocation> locate_pixel(const PixelQuery& query, const CameraView& view,
                                   const VehicleState& vehicle, std::optional<double> last_range_m,
                                   const FrameRay& frame_ray, const PixelLocatorSetup& setup);

}  // namespace k40t::driver
