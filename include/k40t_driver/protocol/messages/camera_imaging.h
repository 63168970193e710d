// Stream and image requests of the common camera family (document sections 3.2.4.8-3.2.4.10,
// 3.2.4.18, 3.2.4.19, 3.2.4.22, 3.2.4.23 and 3.2.4.25): output bitrate, resolution and encoding,
// image mode, focus, OSD watermark, AI recognition and box tracking. Host 0x01/0x01 -> camera
// 0x04/0x01; multi-byte fields low byte first (section 2.1); reserved bytes sent as zero
// (docs/protocol/decisions.md#a11) and optional on receive. Every ACK is the bare response code
// (PlainAck).
#pragma once

#include <array>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/camera_enums.h"
#include "k40t_driver/protocol/messages/setting_request.h"

namespace k40t::protocol {

// Pixel coordinates of focus areas and tracking boxes refer to the 1920x1080 output stream
// (section 3.2.4.25 gives these bounds; 1080P30 is the only supported stream resolution).
constexpr int kStreamWidthPx = 1920;
constexpr int kStreamHeightPx = 1080;

// The document's bounds of a pixel column and row in the stream.
constexpr auto kStreamColumn = wire::u16.range(0, kStreamWidthPx, "px");
constexpr auto kStreamRow = wire::u16.range(0, kStreamHeightPx, "px");

// 0x000308, section 3.2.4.8: output stream bitrate, 1 (1 Mbit/s) .. 6 (12 Mbit/s).
struct StreamBitrateRequest : ByteSettingRequest<StreamBitrateRequest, SettingPrefix::kNone, 1> {
  K40T_POD_MESSAGE(0x000308, "stream_bitrate", "3.2.4.8");

  K40T_SETTING_VALUE(StreamBitrate, bitrate, StreamBitrate::k4Mbps);
};

// 0x00030A, section 3.2.4.9: output resolution, 1 = 1080P30. The document lists 2 = 720P30 as
// "not supported", so validation refuses it (the code is still decoded and named).
struct StreamResolutionRequest
    : ByteSettingRequest<StreamResolutionRequest, SettingPrefix::kNone, 1> {
  K40T_POD_MESSAGE(0x00030A, "stream_resolution", "3.2.4.9");

  K40T_SETTING_VALUE(StreamResolution, resolution, StreamResolution::k1080p30);

  Status validate() const;  // 720P30 has a code but cannot be set
};

// 0x00030B, section 3.2.4.10: output encoding H264 (0) or H265 (1).
struct StreamEncodingRequest : ByteSettingRequest<StreamEncodingRequest, SettingPrefix::kNone, 1> {
  K40T_POD_MESSAGE(0x00030B, "stream_encoding", "3.2.4.10");

  K40T_SETTING_VALUE(VideoEncoding, encoding, VideoEncoding::kH264);
};

// 0x000313, section 3.2.4.18: focus command; the uint16 area corners (top-left, bottom-right)
// are used by area auto focus (4) only and must then span a non-empty box.
struct FocusRequest {
  K40T_POD_REQUEST(0x000313, "focus", "3.2.4.18", 10, 9);
  // Outside area focus the corners are ignored by the pod but must still fit the stream.
  K40T_FIELDS((FocusCommand, command, wire::u8, FocusCommand::kAuto),
              (uint16_t, area_left_px, kStreamColumn), (uint16_t, area_top_px, kStreamRow),
              (uint16_t, area_right_px, kStreamColumn), (uint16_t, area_bottom_px, kStreamRow),
              (reserved, wire::reserved(1)));
  Status extra_checks() const;  // area focus: right of left, below top
};

// 0x000314, section 3.2.4.19: OSD watermark off (0) / on (1), then two reserved bytes.
struct OsdWatermarkRequest : ByteSettingRequest<OsdWatermarkRequest, SettingPrefix::kNone, 2> {
  K40T_POD_MESSAGE(0x000314, "osd_watermark", "3.2.4.19");
  static constexpr uint8_t kOnCode = 1;
  static constexpr uint8_t kOffCode = 0;

  K40T_SETTING_VALUE(bool, enabled, false);
};

// 0x000318, section 3.2.4.22: what the stream shows: 0 infrared, 5/6 visible, 7 split screen.
struct ImageModeRequest : ByteSettingRequest<ImageModeRequest, SettingPrefix::kNone, 1> {
  K40T_POD_MESSAGE(0x000318, "image_mode", "3.2.4.22");

  K40T_SETTING_VALUE(ImageMode, mode, ImageMode::kVisible);
};

// 0x000319, section 3.2.4.23: AI recognition on (1) / off (2), the model to load (0 = default
// YOLO model) and up to 10 target class ids from the model's label file. The document does not
// say how unused slots are marked; they are sent as the caller set them (default 0).
struct AiRecognitionRequest {
  static constexpr size_t kClassSlots = 10;
  K40T_POD_REQUEST(0x000319, "ai_recognition", "3.2.4.23", 2 + kClassSlots, 2 + kClassSlots);
  FeatureSwitch recognition = FeatureSwitch::kOn;
  uint8_t model = 0;
  std::array<uint8_t, kClassSlots> classes{};

  K40T_LAYOUT(s, v) {
    static constexpr const char* kClassNames[kClassSlots] = {
        "class_1", "class_2", "class_3", "class_4", "class_5",
        "class_6", "class_7", "class_8", "class_9", "class_10"};
    v("recognition", s.recognition, wire::u8);
    v("model", s.model, wire::u8);
    for (size_t i = 0; i < kClassSlots; ++i) v(kClassNames[i], s.classes[i], wire::u8);
  }
};

// 0x000324, section 3.2.4.25: box tracking on (1) / off (2) and the box in stream pixels: x, y
// of the top-left corner, width, height (uint16), with x + width <= 1920 and y + height <= 1080.
// The pod needs AI recognition on; the document's table header says "Byte1-2" for the switch but
// its details and the 10-byte total make it one byte.
struct BoxTrackingRequest {
  K40T_POD_REQUEST(0x000324, "box_tracking", "3.2.4.25", 10, 9);
  K40T_FIELDS((FeatureSwitch, tracking, wire::u8, FeatureSwitch::kOn),
              (uint16_t, x_px, kStreamColumn), (uint16_t, y_px, kStreamRow),
              (uint16_t, width_px, wire::u16),  // the box stays inside: extra_checks()
              (uint16_t, height_px, wire::u16), (reserved, wire::reserved(1)));
  Status extra_checks() const;  // x_px + width_px <= 1920, y_px + height_px <= 1080
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using CameraImagingMessages =
    MessageList<StreamBitrateRequest, StreamResolutionRequest, StreamEncodingRequest, FocusRequest,
                OsdWatermarkRequest, ImageModeRequest, AiRecognitionRequest, BoxTrackingRequest>;

}  // namespace k40t::protocol
