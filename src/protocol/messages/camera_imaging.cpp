#include "k40t_driver/protocol/messages/camera_imaging.h"

#include "camera_codec.h"

namespace k40t::protocol {

using camera_codec::get_code;
using camera_codec::put_code;
using camera_codec::read_code;

// ---- 0x000308 ------------------------------------------------------------------------------
Status StreamBitrateRequest::validate() const {
  return check_enum("bitrate", bitrate);
}
void StreamBitrateRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, bitrate, 1);
}
Status StreamBitrateRequest::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, bitrate);
}

// ---- 0x00030A ------------------------------------------------------------------------------
Status StreamResolutionRequest::validate() const {
  if (resolution == StreamResolution::k720p30) {
    return Status::fail(
        "field 'resolution': 2 (720P30) is not supported by the pod (section 3.2.4.9); use 1 "
        "(1080P30)");
  }
  return check_enum("resolution", resolution);
}
void StreamResolutionRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, resolution, 1);
}
Status StreamResolutionRequest::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, resolution);
}

// ---- 0x00030B ------------------------------------------------------------------------------
Status StreamEncodingRequest::validate() const {
  return check_enum("encoding", encoding);
}
void StreamEncodingRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, encoding, 1);
}
Status StreamEncodingRequest::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, encoding);
}

// ---- 0x000313 ------------------------------------------------------------------------------
Status FocusRequest::validate() const {
  // Outside area focus the corners are ignored by the pod but must still fit the stream.
  const bool area = command == FocusCommand::kArea;
  const int64_t min_right = area ? area_left_px + 1 : 0;
  const int64_t min_bottom = area ? area_top_px + 1 : 0;
  return first_failure(
      check_enum("command", command),
      camera_codec::check_int("area_left_px", area_left_px, 0, kStreamWidthPx, "px"),
      camera_codec::check_int("area_top_px", area_top_px, 0, kStreamHeightPx, "px"),
      camera_codec::check_int("area_right_px", area_right_px, min_right, kStreamWidthPx, "px"),
      camera_codec::check_int("area_bottom_px", area_bottom_px, min_bottom, kStreamHeightPx, "px"));
}

void FocusRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, command);
  for (uint16_t v : {area_left_px, area_top_px, area_right_px, area_bottom_px}) w.u16(v);
  w.zeros(1);
}

Status FocusRequest::decode(ByteReader& r, const CodecOptions&) {
  command = get_code<FocusCommand>(r);
  for (uint16_t* v : {&area_left_px, &area_top_px, &area_right_px, &area_bottom_px}) *v = r.u16();
  return Status::ok();
}

// ---- 0x000314 ------------------------------------------------------------------------------
void OsdWatermarkRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.u8(enabled ? 1 : 0);
  w.zeros(2);
}

Status OsdWatermarkRequest::decode(ByteReader& r, const CodecOptions&) {
  return camera_codec::get_flag(r, "enabled", enabled);
}

// ---- 0x000318 ------------------------------------------------------------------------------
Status ImageModeRequest::validate() const {
  return check_enum("mode", mode);
}
void ImageModeRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, mode, 1);
}
Status ImageModeRequest::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, mode);
}

// ---- 0x000319 ------------------------------------------------------------------------------
Status AiRecognitionRequest::validate() const {
  return check_enum("recognition", recognition);
}

void AiRecognitionRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, recognition);
  w.u8(model);
  for (uint8_t c : classes) w.u8(c);
}

Status AiRecognitionRequest::decode(ByteReader& r, const CodecOptions&) {
  recognition = get_code<FeatureSwitch>(r);
  model = r.u8();
  for (uint8_t& c : classes) c = r.u8();
  return Status::ok();
}

// ---- 0x000324 ------------------------------------------------------------------------------
Status BoxTrackingRequest::validate() const {
  // x and y are checked first so that the width/height bounds below are never negative.
  const Status corner =
      first_failure(check_enum("tracking", tracking),
                    camera_codec::check_int("x_px", x_px, 0, kStreamWidthPx, "px"),
                    camera_codec::check_int("y_px", y_px, 0, kStreamHeightPx, "px"));
  if (!corner) return corner;
  return first_failure(camera_codec::check_int("width_px", width_px, 0, kStreamWidthPx - x_px,
                                               "px (x_px + width_px <= 1920)"),
                       camera_codec::check_int("height_px", height_px, 0, kStreamHeightPx - y_px,
                                               "px (y_px + height_px <= 1080)"));
}

void BoxTrackingRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, tracking);
  for (uint16_t v : {x_px, y_px, width_px, height_px}) w.u16(v);
  w.zeros(1);
}

Status BoxTrackingRequest::decode(ByteReader& r, const CodecOptions&) {
  tracking = get_code<FeatureSwitch>(r);
  for (uint16_t* v : {&x_px, &y_px, &width_px, &height_px}) *v = r.u16();
  return Status::ok();
}

}  // namespace k40t::protocol
