#include "k40t_driver/protocol/messages/camera_system.h"

#include "camera_codec.h"

namespace k40t::protocol {

using camera_codec::check_ipv4;
using camera_codec::get_code;
using camera_codec::put_code;

// ---- 0x00030C, 0x00030D, 0x00030F, 0x000312, 0x000316, 0x000317 --------------------------------
void FixedCommandRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.u8(kCommandByte);
  w.zeros(1);
}

Status FixedCommandRequest::decode(ByteReader& r, const CodecOptions&) {
  return camera_codec::expect_byte(r, kCommandByte, "the command code");
}

// ---- 0x00030E ------------------------------------------------------------------------------
Status TimeSyncRequest::validate() const {
  // Time zones run from UTC-12 (720 minutes west) to UTC+14 (840 minutes east).
  return first_failure(
      camera_codec::check_int("unix_time_ms", unix_time_ms, 0, std::numeric_limits<int64_t>::max(),
                              "ms"),
      camera_codec::check_int("tz_minutes_west", tz_minutes_west, -840, 720, "min"));
}

void TimeSyncRequest::encode(ByteWriter& w, const CodecOptions&) const {
  w.i64(unix_time_ms);
  w.i32(tz_minutes_west);
  w.i32(tz_dst_type);
}

Status TimeSyncRequest::decode(ByteReader& r, const CodecOptions&) {
  unix_time_ms = r.i64();
  tz_minutes_west = r.i32();
  tz_dst_type = r.i32();
  return Status::ok();
}

// ---- 0x000311 ------------------------------------------------------------------------------
namespace {
Status check_netmask(const char* field, const std::string& text) {
  const Status parsed = check_ipv4(field, text);
  if (!parsed) return parsed;
  const uint32_t inverted = ~camera_codec::ipv4_value(text);
  if ((inverted & (inverted + 1)) == 0) return Status::ok();  // ones, then only zeros
  return Status::fail(std::string("field '") + field +
                      "' must be a contiguous netmask like 255.255.255.0, got '" + text + "'");
}

void put_octets(ByteWriter& w, const std::string& address) {
  for (uint8_t octet : camera_codec::ipv4_octets(address)) w.u8(octet);
}

std::string get_octets(ByteReader& r) {
  camera_codec::Ipv4Octets octets{};
  for (uint8_t& octet : octets) octet = r.u8();
  return camera_codec::ipv4_text(octets);
}
}  // namespace

Status SetIpRequest::validate() const {
  const Status parsed =
      first_failure(check_enum("mode", mode), check_ipv4("address", address),
                    check_netmask("netmask", netmask), check_ipv4("gateway", gateway));
  if (!parsed) return parsed;
  if (mode == IpMode::kStatic && camera_codec::ipv4_value(address) == 0) {
    return Status::fail("field 'address' must not be 0.0.0.0 with mode 0 (static)");
  }
  return Status::ok();
}

void SetIpRequest::encode(ByteWriter& w, const CodecOptions&) const {
  put_code(w, mode);
  put_octets(w, address);
  put_octets(w, netmask);
  put_octets(w, gateway);
}

Status SetIpRequest::decode(ByteReader& r, const CodecOptions&) {
  mode = get_code<IpMode>(r);
  address = get_octets(r);
  netmask = get_octets(r);
  gateway = get_octets(r);
  return Status::ok();
}

// ---- ACK 0x010312 --------------------------------------------------------------------------
Status GetIpAck::validate() const {
  return first_failure(check_ipv4("address", address), check_ipv4("netmask", netmask),
                       check_ipv4("gateway", gateway));
}

// Section 3.2.4.17 lists each octet as a byte of its own (Byte3..Byte6 the address, first octet
// first), like 0x000311's request: they are bytes, not a uint32, so ack_byte_order (which orders
// the response code) does not reverse them.
void GetIpAck::encode(ByteWriter& w, const CodecOptions& o) const {
  w.u16(static_cast<uint16_t>(code), o.ack_byte_order);
  for (const std::string* ip : {&address, &netmask, &gateway}) put_octets(w, *ip);
}

Status GetIpAck::decode(ByteReader& r, const CodecOptions& o) {
  code = static_cast<ResponseCode>(r.u16(o.ack_byte_order));
  if (r.remaining() == 0) return Status::ok();  // a refusal: code only
  for (std::string* ip : {&address, &netmask, &gateway}) *ip = get_octets(r);
  return Status::ok();
}

// ---- ACK 0x010317 --------------------------------------------------------------------------
std::string CameraVersionAck::version_text() const {
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

void CameraVersionAck::encode(ByteWriter& w, const CodecOptions& o) const {
  w.u16(static_cast<uint16_t>(code), o.ack_byte_order);
  for (uint8_t v : {major, minor, patch}) w.u8(v);
}

Status CameraVersionAck::decode(ByteReader& r, const CodecOptions& o) {
  code = static_cast<ResponseCode>(r.u16(o.ack_byte_order));
  if (r.remaining() == 0) return Status::ok();  // a refusal: code only
  for (uint8_t* v : {&major, &minor, &patch}) *v = r.u8();
  return Status::ok();
}

}  // namespace k40t::protocol
