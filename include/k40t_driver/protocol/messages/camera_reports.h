// Periodic reports of the camera (document sections 3.2.1.1 and 3.2.1.4): camera system status
// 0x000003 and upgrade/repair progress 0x000008, both 1 Hz, camera 0x04/0x01 -> host. Multi-byte
// fields low byte first (section 2.1); the trailing reserved byte is optional on receive.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/camera_enums.h"

namespace k40t::protocol {

// One count of the SD capacities of 0x000003 in MB as the layout reads it. The document writes
// the unit as "MB*10" (单位: MB*10); 10 MB per count, since 0.1 MB would cap a card at 6.5 GB. A
// pod that means 0.1 MB is the reading sd_capacity_unit (docs/protocol/decisions.md#conventions),
// applied after decoding (convention_readings.h).
constexpr double kSdCapacityUnitMb = 10.0;
constexpr double kSdCapacityMaxMb = 65535 * kSdCapacityUnitMb;

// 0x000003, section 3.2.1.1, 1 Hz: the camera's modes, stream settings and SD card.
// The photo settings (photo_mode, time_lapse_interval_s, burst_count) are PhotoSettings'.
struct CameraSystemStatus : PhotoSettings {
  K40T_POD_REPORT(0x000003, "camera_system_status", "3.2.1.1", 16, 15);
  CaptureMode capture_mode = CaptureMode::kPhoto;
  // docs/protocol/decisions.md#a6: the "encoding format" byte is the resolution.
  ReportedStreamResolution stream_resolution = ReportedStreamResolution::k1080p30;
  VideoEncoding encoding = VideoEncoding::kH264;
  ImageMode image_mode = ImageMode::kVisible;  // "stream mode": what the stream shows
  StreamBitrate bitrate = StreamBitrate::k4Mbps;
  SdCardState sd_state = SdCardState::kNormal;
  double sd_total_mb = 0;  // uint16 counts of kSdCapacityUnitMb on the wire
  double sd_free_mb = 0;
  double sd_used_mb = 0;

  K40T_LAYOUT(s, v) {
    constexpr auto capacity =
        wire::scaled<uint16_t>(1.0 / kSdCapacityUnitMb).range(0.0, kSdCapacityMaxMb, "MB");
    v("capture_mode", s.capture_mode, wire::u8);
    v("stream_resolution", s.stream_resolution, wire::u8);
    v("encoding", s.encoding, wire::u8);
    v("image_mode", s.image_mode, wire::u8);
    v("bitrate", s.bitrate, wire::u8);
    photo_settings(s, v);
    v("sd_state", s.sd_state, wire::u8);
    v("sd_total_mb", s.sd_total_mb, capacity);
    v("sd_free_mb", s.sd_free_mb, capacity);
    v("sd_used_mb", s.sd_used_mb, capacity);
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// 0x000008, section 3.2.1.4, 1 Hz: camera upgrade or repair state and progress 0..100 %.
struct CameraUpgradeStatus {
  K40T_POD_REPORT(0x000008, "camera_upgrade_status", "3.2.1.4", 3, 2);
  K40T_FIELDS((CameraUpgradeState, state, wire::u8, CameraUpgradeState::kSucceeded),
              (uint8_t, progress_percent, wire::u8.range(0, 100, "%")),  // 0 start, 100 complete
              (reserved, wire::reserved(1)));
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using CameraReportMessages = MessageList<CameraSystemStatus, CameraUpgradeStatus>;

}  // namespace k40t::protocol
