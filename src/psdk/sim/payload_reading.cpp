#include "k40t_driver/psdk/sim/payload_reading.h"

namespace k40t::psdk::sim {

namespace {

uint16_t le16(const Data& d, size_t at) {
  return static_cast<uint16_t>(d.bytes[at] | d.bytes[at + 1] << 8);
}
uint32_t le32(const Data& d, size_t at) {
  return static_cast<uint32_t>(d.bytes[at]) | static_cast<uint32_t>(d.bytes[at + 1]) << 8 |
         static_cast<uint32_t>(d.bytes[at + 2]) << 16 |
         static_cast<uint32_t>(d.bytes[at + 3]) << 24;
}

Status need(const Data& d, size_t size, const char* what) {
  if (d.size < 1) return Status::fail(std::string(what) + ": empty ACK");
  if (d.bytes[0] != 0x00)
    return Status::fail(std::string(what) + ": return code " + std::to_string(d.bytes[0]));
  if (d.size < size)
    return Status::fail(std::string(what) + ": " + std::to_string(d.size) + " bytes, need " +
                        std::to_string(size));
  return Status::ok();
}

// 3.5.1 mode byte. Document: 0 free, 1 following, 2 FPV. Headers (one enum with 3.5.2):
// 0 free, 1 FPV, 2 yaw follow.
const char* const kModesDocument[] = {"free", "following", "FPV"};
const char* const kModesHeaders[] = {"free", "FPV", "following"};
// 3.5.2's numbering of the same names (document and headers agree here).
uint8_t set_code(const std::string& mode) {
  return mode == "free" ? 0 : mode == "FPV" ? 1 : 2;
}

// 3.4.9 state word: the bit of each flag read here (-1: the layout has none).
struct SdBits {
  int inserted, read_only, full, has_error;
};
constexpr SdBits kSdDocument{0, 2, 5, 8};  // 0 inserted, 2 read-only, 5 full, 8 error
constexpr SdBits kSdHeaders{0, 3, 5, 7};   // 0 inserted, 3 read-only, 5 full, 7 error

bool bit(uint16_t word, int at) {
  return at >= 0 && (word >> at & 1u) != 0;
}

}  // namespace

bool parse_payload_reading(const std::string& text, PayloadReading& out) {
  if (text == "dji_headers")
    out = PayloadReading::kDjiHeaders;
  else if (text == "document")
    out = PayloadReading::kDocument;
  else
    return false;
  return true;
}

Result<GimbalStateReading> read_gimbal_state(const Data& ack, PayloadReading reading) {
  // code, mode, flags, pitch, roll, yaw (int16, 0.1 degree).
  const Status ok = need(ack, 9, "gimbal state");
  if (!ok) return ok;
  const uint8_t mode = ack.bytes[1];
  if (mode > 2) return Status::fail("gimbal state: mode " + std::to_string(mode));
  GimbalStateReading out;
  out.mode = reading == PayloadReading::kDocument ? kModesDocument[mode] : kModesHeaders[mode];
  out.set_mode_code = set_code(out.mode);
  out.pitch_deg = static_cast<int16_t>(le16(ack, 3)) / 10.0;
  out.roll_deg = static_cast<int16_t>(le16(ack, 5)) / 10.0;
  out.yaw_deg = static_cast<int16_t>(le16(ack, 7)) / 10.0;
  return out;
}

Result<SdCardReading> read_sd_card(const Data& ack, PayloadReading reading) {
  // code, state word (2), total MB, free MB, shots, record time (uint32 each).
  const Status ok = need(ack, 19, "SD card");
  if (!ok) return ok;
  const uint16_t word = le16(ack, 1);
  const SdBits& b = reading == PayloadReading::kDocument ? kSdDocument : kSdHeaders;
  SdCardReading out;
  out.inserted = bit(word, b.inserted);
  out.read_only = bit(word, b.read_only);
  out.full = bit(word, b.full);
  out.has_error = bit(word, b.has_error);
  out.total_mb = le32(ack, 3);
  out.free_mb = le32(ack, 7);
  return out;
}

Result<ShootPhotoModeReading> read_shoot_photo_mode(const Data& ack, PayloadReading reading) {
  // code, type, burst count, interval count, interval (1 byte, or 2 in the headers).
  const bool wide = reading == PayloadReading::kDjiHeaders;
  const Status ok = need(ack, wide ? 6 : 5, "shoot photo mode");
  if (!ok) return ok;
  ShootPhotoModeReading out;
  out.type = ack.bytes[1];
  out.burst_count = ack.bytes[2];
  out.interval_count = ack.bytes[3];
  out.interval_s = wide ? le16(ack, 4) : ack.bytes[4];
  return out;
}

}  // namespace k40t::psdk::sim
