#include "k40t_driver/protocol/messages/camera_status.h"

#include "camera_codec.h"

namespace k40t::protocol {

using camera_codec::get_code;
using camera_codec::put_code;
using camera_codec::read_code;

namespace {
// Every frame with a lens mode and a state: 0x020302, 0x020303, 0x020307.
template <class Frame>
Status validate_lens_and_state(const Frame& m) {
  return first_failure(check_enum("lens", m.lens), check_enum("state", m.state));
}

// 0x020302 and 0x020303: lens mode, state, a uint16 count, 3 reserved.
template <class Frame>
void encode_counted(const Frame& m, uint16_t count, ByteWriter& w) {
  put_code(w, m.lens);
  put_code(w, m.state);
  w.u16(count);
  w.zeros(3);
}

template <class Frame>
Status decode_counted(Frame& m, uint16_t& count, ByteReader& r) {
  m.lens = get_code<decltype(m.lens)>(r);
  m.state = get_code<decltype(m.state)>(r);
  count = r.u16();
  return Status::ok();
}
}  // namespace

// ---- 0x020302 ------------------------------------------------------------------------------
Status PhotoStatus::validate() const {
  return validate_lens_and_state(*this);
}
void PhotoStatus::encode(ByteWriter& w, const CodecOptions&) const {
  encode_counted(*this, burst_count, w);
}
Status PhotoStatus::decode(ByteReader& r, const CodecOptions&) {
  return decode_counted(*this, burst_count, r);
}

// ---- 0x020303 ------------------------------------------------------------------------------
Status RecordStatus::validate() const {
  return validate_lens_and_state(*this);
}
void RecordStatus::encode(ByteWriter& w, const CodecOptions&) const {
  encode_counted(*this, recording_time_s, w);
}
Status RecordStatus::decode(ByteReader& r, const CodecOptions&) {
  return decode_counted(*this, recording_time_s, r);
}

// ---- 0x020304 ------------------------------------------------------------------------------
Status ZoomStatus::validate() const {
  return check_enum("progress", progress);
}
void ZoomStatus::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, progress, 1);
}
Status ZoomStatus::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, progress);
}

// ---- 0x020307 ------------------------------------------------------------------------------
Status PreciseReshootStatus::validate() const {
  return validate_lens_and_state(*this);
}

void PreciseReshootStatus::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, lens);
  put_code(w, state, 5);
}

Status PreciseReshootStatus::decode(ByteReader& r, const CodecOptions&) {
  lens = get_code<PhotoLensMode>(r);
  return read_code(r, state);
}

// ---- 0x02030C ------------------------------------------------------------------------------
Status TfCardUpgradeStatus::validate() const {
  return check_enum("state", state);
}
void TfCardUpgradeStatus::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, state, 1);
}
Status TfCardUpgradeStatus::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, state);
}

// ---- 0x02030D ------------------------------------------------------------------------------
Status SdFormatStatus::validate() const {
  return check_enum("state", state);
}
void SdFormatStatus::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, state, 2);
}
Status SdFormatStatus::decode(ByteReader& r, const CodecOptions&) {
  return read_code(r, state);
}

}  // namespace k40t::protocol
