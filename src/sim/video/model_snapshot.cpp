#include "k40t_driver/sim/video/model_snapshot.h"

#include <functional>

namespace k40t::sim::video {

namespace {

ImageMode image_mode_of(uint8_t code) {
  // Codes the document does not define (1..4) show the visible image, like 5.
  return is_image_mode(code) ? static_cast<ImageMode>(code) : ImageMode::kVisible;
}

// Changes whenever a temperature the world returns can change.
uint64_t fingerprint(const WorldConfig& w) {
  uint64_t h = 1469598103934665603ULL;
  for (double v :
       {w.ground_height_m, w.ground_temperature_degC, w.ground_texture_degC, w.sky_zenith_degC,
        w.sky_horizon_degC, w.hot.north_m, w.hot.east_m, w.hot.radius_m, w.hot.temperature_degC,
        w.cold.north_m, w.cold.east_m, w.cold.radius_m, w.cold.temperature_degC}) {
    h = (h ^ std::hash<double>{}(v)) * 1099511628211ULL;
  }
  return h;
}

}  // namespace

VideoSnapshot snapshot_of(const PodModel& model) {
  VideoSnapshot s;
  const CameraSettings& camera = model.camera().settings();
  s.image_mode = image_mode_of(camera.image_mode);
  s.resolution = camera.stream_resolution == 1 ? StreamResolution::k720p : StreamResolution::k1080p;
  s.palette = static_cast<int>(model.thermal().settings().reported.palette);
  s.thermal_zoom = model.thermal().settings().reported.zoom_x;
  s.hybrid_zoom = model.zoom().zoom();
  s.yaw_deg = model.boresight_yaw_deg();
  s.pitch_deg = model.boresight_pitch_deg();
  const World world = model.world();
  s.temperature = [world](const Vec3& d) { return world.trace(d).temperature_degC; };
  s.scene_version = fingerprint(world.config());
  return s;
}

}  // namespace k40t::sim::video
