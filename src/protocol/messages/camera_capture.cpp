#include "k40t_driver/protocol/messages/camera_capture.h"

#include "camera_codec.h"

namespace k40t::protocol {

using camera_codec::expect_byte;
using camera_codec::get_code;
using camera_codec::put_code;
using camera_codec::read_code;

namespace {

Status check_zoom(const char* field, double zoom_x) {
  return check_range(field, zoom_x, kMinZoomRatio, kMaxZoomRatio, "x");
}

}  // namespace

// ---- 0x000300 ------------------------------------------------------------------------------
Status CaptureModeRequest::validate() const {
  return check_enum("mode", mode);
}

void CaptureModeRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, mode, 1);
}
Status CaptureModeRequest::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, mode);
}

// ---- 0x000301 ------------------------------------------------------------------------------
Status PhotoSettingsRequest::validate() const {
  return first_failure(check_enum("photo_mode", photo_mode),
                       camera_codec::check_photo_settings(time_lapse_interval_s, burst_count));
}

void PhotoSettingsRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, photo_mode);
  w.u8(time_lapse_interval_s);
  w.u8(burst_count);
  w.zeros(1);
}

Status PhotoSettingsRequest::decode(ByteReader& r, const CodecOptions&) {
  photo_mode = get_code<PhotoMode>(r);
  time_lapse_interval_s = r.u8();
  burst_count = r.u8();
  return Status::ok();
}

// ---- 0x000302 and 0x000303: lens, action, folder, name -------------------------------------
template <class Lens, class Action>
Status FileCaptureRequest<Lens, Action>::validate() const {
  return first_failure(check_enum("lens", lens), check_enum("action", action),
                       check_text("folder", folder, kCameraFolderBytes),
                       check_text("name", name, kCameraFileNameBytes));
}

template <class Lens, class Action>
void FileCaptureRequest<Lens, Action>::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, lens);
  put_code(w, action);
  w.text(folder, kCameraFolderBytes);
  w.text(name, kCameraFileNameBytes);
}

template <class Lens, class Action>
Status FileCaptureRequest<Lens, Action>::decode(ByteReader& r, const CodecOptions&) {
  lens = get_code<Lens>(r);
  action = get_code<Action>(r);
  folder = r.text(kCameraFolderBytes);
  name = r.text(kCameraFileNameBytes);
  return Status::ok();
}

template struct FileCaptureRequest<PhotoLensMode, PhotoAction>;
template struct FileCaptureRequest<RecordLensMode, RecordAction>;

// ---- 0x000304 ------------------------------------------------------------------------------
Status ZoomRatioRequest::validate() const {
  return check_zoom("zoom_x", zoom_x);
}

void ZoomRatioRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.u8(0x00);  // "start setting"
  w.u16(to_wire<uint16_t>(zoom_x, 10));
}

Status ZoomRatioRequest::decode(ByteReader& r, const CodecOptions&) {
  const Status start = expect_byte(r, 0x00, "start setting");
  zoom_x = r.u16() / 10.0;
  return start;
}

// ---- 0x000306 ------------------------------------------------------------------------------
Status ContinuousZoomRequest::validate() const {
  return check_enum("command", command);
}

void ContinuousZoomRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, command, 1);
}
Status ContinuousZoomRequest::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, command);
}

// ---- 0x000307 ------------------------------------------------------------------------------
Status PreciseReshootRequest::validate() const {
  return first_failure(check_enum("lens", lens), check_enum("resolution", resolution),
                       check_zoom("zoom_x", zoom_x),
                       check_text("folder", folder, kCameraFolderBytes),
                       check_text("name", name, kCameraFileNameBytes));
}

void PreciseReshootRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, lens);
  put_code(w, resolution);
  w.u16(to_wire<uint16_t>(zoom_x, 10));
  w.u16(focal_length_raw);
  w.text(folder, kCameraFolderBytes);
  w.text(name, kCameraFileNameBytes);
}

Status PreciseReshootRequest::decode(ByteReader& r, const CodecOptions&) {
  lens = get_code<PhotoLensMode>(r);
  resolution = get_code<ReshootResolution>(r);
  zoom_x = r.u16() / 10.0;
  focal_length_raw = r.u16();
  folder = r.text(kCameraFolderBytes);
  name = r.text(kCameraFileNameBytes);
  return Status::ok();
}

}  // namespace k40t::protocol
