// Capture requests of the common camera family (document section 3.2.4.1-3.2.4.7): photo/video
// mode, photo settings, take photo, record, zoom and precise re-shoot. Host 0x01/0x01 -> camera
// 0x04/0x01; multi-byte fields low byte first (section 2.1); reserved bytes sent as zero
// (docs/protocol/decisions.md#a11) and optional on receive. Every ACK is the bare response code
// (PlainAck). Their status frames are in camera_status.h.
#pragma once

#include <string>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/camera_enums.h"
#include "k40t_driver/protocol/messages/setting_request.h"

namespace k40t::protocol {

// Widths of the folder and file name text fields of 0x000302, 0x000303 and 0x000307: no NUL
// terminator when full; empty means "root folder" / "default name".
constexpr size_t kCameraFolderBytes = 20;
constexpr size_t kCameraFileNameBytes = 32;

// The hybrid (optical + digital) zoom range of 0x000304 and 0x000307, as a ratio.
constexpr double kMinZoomRatio = 1.0;
constexpr double kMaxZoomRatio = 160.0;

// The zoom ratio of 0x000304 and 0x000307: uint16 x10 on the wire.
constexpr auto kZoomRatioWire = wire::scaled<uint16_t>(10).range(kMinZoomRatio, kMaxZoomRatio, "x");

// The folder (20 bytes) and file name (32 bytes) that 0x000302, 0x000303 and 0x000307 end with;
// empty texts mean the root folder and the pod's default naming.
struct SaveAs {
  std::string folder;
  std::string name;

  template <class S, class V>
  static void body(S& s, V&& v) {
    v("folder", s.folder, wire::Text{kCameraFolderBytes, false});
    v("name", s.name, wire::Text{kCameraFileNameBytes, false});
  }
};

// The photo settings 0x000301 sets and 0x000003 reports: photo mode, time-lapse interval
// (5/7/30/60 s) and burst count (3/5). The pod reports all three whatever the mode, so all three
// are always validated.
struct PhotoSettings {
  PhotoMode photo_mode = PhotoMode::kSingle;
  uint8_t time_lapse_interval_s = 5;
  uint8_t burst_count = 3;

  Status extra_checks() const;  // interval and burst count: the document's few values
};
// Their lines in a layout.
template <class S, class V>
void photo_settings(S& s, V&& v) {
  v("photo_mode", s.photo_mode, wire::u8);
  v("time_lapse_interval_s", s.time_lapse_interval_s, wire::u8);
  v("burst_count", s.burst_count, wire::u8);
}

// 0x000300, section 3.2.4.1: photo or video mode. In photo mode the pod ignores record requests
// and vice versa.
struct CaptureModeRequest : ByteSettingRequest<CaptureModeRequest, SettingPrefix::kNone, 1> {
  K40T_POD_MESSAGE(0x000300, "capture_mode", "3.2.4.1");

  K40T_SETTING_VALUE(CaptureMode, mode, CaptureMode::kPhoto);
};

// 0x000301, section 3.2.4.2: the photo settings, 1 reserved.
struct PhotoSettingsRequest : PhotoSettings {
  K40T_POD_REQUEST(0x000301, "photo_settings", "3.2.4.2", 4, 3);
  K40T_LAYOUT(s, v) {
    photo_settings(s, v);
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// What 0x000302 and 0x000303 share (54 bytes): which cameras, start/stop, then where to save.
template <class Lens, class Action>
struct FileCaptureRequest : SaveAs {
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 2 + kCameraFolderBytes + kCameraFileNameBytes;  // 54
  static constexpr size_t kMinSize = kSize;
  using Ack = PlainAck;

  Lens lens = Lens::kDefault;
  Action action = Action::kStart;

  K40T_LAYOUT(s, v) {
    v("lens", s.lens, wire::u8);
    v("action", s.action, wire::u8);
    body(s, v);
  }
};

// 0x000302, section 3.2.4.3: take a photo (action 0), or stop a burst (1). Status frame 0x020302
// follows except for single shots; the pod asks for GPS (0x000310) before shooting.
struct TakePhotoRequest : FileCaptureRequest<PhotoLensMode, PhotoAction> {
  K40T_POD_MESSAGE(0x000302, "take_photo", "3.2.4.3");
};

// 0x000303, section 3.2.4.4: start (1) or stop (2) recording; status frame 0x020303 at 1 Hz.
// Starting twice does not stop a recording.
struct RecordRequest : FileCaptureRequest<RecordLensMode, RecordAction> {
  K40T_POD_MESSAGE(0x000303, "record", "3.2.4.4");
};

// 0x000304, section 3.2.4.5: byte 1 = 0x00 "start setting", uint16 zoom ratio x10 (1.0..160.0x).
// Status frame 0x020304 tells when the zoom has arrived.
struct ZoomRatioRequest {
  K40T_POD_REQUEST(0x000304, "zoom_ratio", "3.2.4.5", 3, 3);
  K40T_FIELDS((start, wire::fixed(kStartSettingByte, "start setting")),
              (double, zoom_x, kZoomRatioWire, 1.0));
};

// 0x000306, section 3.2.4.6: continuous zoom in/out, stop, or one step in/out.
struct ContinuousZoomRequest : ByteSettingRequest<ContinuousZoomRequest, SettingPrefix::kNone, 1> {
  K40T_POD_MESSAGE(0x000306, "continuous_zoom", "3.2.4.6");

  K40T_SETTING_VALUE(ZoomCommand, command, ZoomCommand::kStop);
};

// 0x000307, section 3.2.4.7: take a photo at a given visible resolution, zoom and focus position
// (the values a previous shot reported in 0x000005), into folder/name. Status frame 0x020307.
// The focus position has no unit in the document: it is passed through as the raw uint16.
struct PreciseReshootRequest : SaveAs {
  K40T_POD_REQUEST(0x000307, "precise_reshoot", "3.2.4.7", 58, 58);
  PhotoLensMode lens = PhotoLensMode::kDefault;
  ReshootResolution resolution = ReshootResolution::k4000x3000;
  double zoom_x = 1.0;  // uint16 x10 on the wire
  uint16_t focal_length_raw = 0;

  K40T_LAYOUT(s, v) {
    v("lens", s.lens, wire::u8);
    v("resolution", s.resolution, wire::u8);
    v("zoom_x", s.zoom_x, kZoomRatioWire);
    v("focal_length_raw", s.focal_length_raw, wire::u16);
    body(s, v);
  }
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using CameraCaptureMessages =
    MessageList<CaptureModeRequest, PhotoSettingsRequest, TakePhotoRequest, RecordRequest,
                ZoomRatioRequest, ContinuousZoomRequest, PreciseReshootRequest>;

}  // namespace k40t::protocol
