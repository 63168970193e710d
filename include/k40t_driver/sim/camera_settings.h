// Every camera setting the pod stores and returns (read-all 0x000200, status 0x000003 and
// 0x000005). Codes the model does not interpret are kept as the document's numbers; those that
// drive the simulation (shutter, ISO, resolutions, bitrates) have their meaning here.
#pragma once

#include <cstdint>

#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::sim {

enum class CaptureMode : uint8_t { kPhoto = 0, kVideo = 1 };
enum class PhotoMode : uint8_t { kSingle = 0, kBurst = 1, kTimeLapse = 2 };

// Common part (3.2.4) and the stream (0x000003).
struct CameraSettings {
  CaptureMode capture_mode = CaptureMode::kPhoto;
  PhotoMode photo_mode = PhotoMode::kSingle;
  uint8_t time_lapse_interval_s = 5;  // 5/7/30/60
  uint8_t burst_count = 3;            // 3/5
  uint8_t stream_resolution = 0;      // 0x000003 byte 2: 0 1080P30, 1 720P30
  uint8_t stream_encoding = 0;        // 0 H264, 1 H265
  uint8_t stream_bitrate = 5;         // 1..6: 1, 1.5, 2, 4, 8, 12 Mbit/s
  uint8_t image_mode = 5;             // 0 IR, 5/6 visible, 7 split screen
  bool watermark = false;
  uint16_t precise_focal_length_raw = 0;  // last 0x000307's focal length, reported by 0x000005
};

// Visible camera (3.2.3): the settings the pod reports in the read-all ACK 0x010200 are kept as
// that ACK itself (the protocol's struct, with the simulated pod's factory defaults), so a
// reported setting needs no field of its own here: its request handler writes the ACK field and
// the read-all returns it. (The OSD watermark, byte 16, is CameraSettings::watermark: 0x000003
// reports it too.)
using VisibleSettings = protocol::VisibleSettingsAck;
VisibleSettings factory_visible_settings();

// Exposure time of a manual shutter code, in microseconds (0 for auto or an unknown code).
double shutter_code_us(uint8_t code);
// Sensor gain of an ISO code in dB relative to ISO 100 (auto reads ISO 100).
double iso_code_db(uint8_t code);
// Stream bitrate of code 1..6 in Mbit/s (0 for others).
double stream_bitrate_mbps(uint8_t code);
// Visible recording bitrate for the resolution and bitrate codes (H.264 table of 3.2.3.1).
double visible_video_mbps(uint8_t resolution, uint8_t bitrate);

}  // namespace k40t::sim
