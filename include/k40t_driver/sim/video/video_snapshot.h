// What the simulated pod's video stream shows at one instant, as plain data: the renderer draws a
// frame from this and nothing else, so it can be fed by the standalone k40t_video_sim (its own
// settings) or by the live pod model (k40t_sim --rtsp-port).
#pragma once

#include <cstdint>
#include <functional>

#include "k40t_driver/sim/geometry.h"

namespace k40t::sim::video {

// Content of the stream (0x000318 / 0x000003 byte 4).
enum class ImageMode : uint8_t { kThermal = 0, kVisible = 5, kVisibleAlt = 6, kSplit = 7 };
bool is_image_mode(int code);

// Temperature (degC) of whatever a ray from the pod along the unit vector `direction` (world
// frame of sim/geometry.h: x north, y east, z up) meets first — World::trace() for the pod model.
using TemperatureSampler = std::function<double(const Vec3& direction)>;

// Stream resolution of the visible and split-screen images (0x000003 byte 2,
// docs/protocol/decisions.md#a6). The thermal image is always streamed at the core's 640x512.
enum class StreamResolution : uint8_t { k1080p = 0, k720p = 1 };

struct VideoSnapshot {
  ImageMode image_mode = ImageMode::kVisible;
  StreamResolution resolution = StreamResolution::k1080p;
  int palette = 1;                 // 1..20 (0x000106)
  double hybrid_zoom = 1;          // telephoto, 1..160 (0x000005 bytes 4-5)
  int thermal_zoom = 1;            // thermal digital zoom, 1..8 (0x000105)
  double yaw_deg = 0;              // boresight heading in the world, positive to the right
  double pitch_deg = 0;            // boresight elevation, positive up
  TemperatureSampler temperature;  // empty: a uniform 20 degC scene
  // Bumped by the owner whenever what `temperature` returns changes for the same direction, so
  // the renderer knows its cached thermal field is stale.
  uint64_t scene_version = 0;
};

}  // namespace k40t::sim::video
