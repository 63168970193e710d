#include "camera_codec.h"

#include <arpa/inet.h>

#include <cstdio>

namespace k40t::protocol::camera_codec {

Status expect_byte(ByteReader& r, uint8_t expected, const char* meaning) {
  const uint8_t got = r.u8();
  if (!r.ok() || got == expected) return Status::ok();  // a short payload is reported by the caller
  char buffer[120];
  std::snprintf(buffer, sizeof(buffer), "byte %zu must be 0x%02X (%s), got 0x%02X", r.position(),
                expected, meaning, got);
  return Status::fail(buffer);
}

Status get_flag(ByteReader& r, const char* field, bool& out) {
  const uint8_t got = r.u8();
  if (got > 1) {
    return Status::fail(std::string("field '") + field + "' must be 0 or 1, got " +
                        std::to_string(got));
  }
  out = got == 1;
  return Status::ok();
}

Status check_one_of(const char* field, int64_t value, std::initializer_list<int64_t> allowed,
                    const char* unit) {
  std::string list;
  for (int64_t a : allowed) {
    if (a == value) return Status::ok();
    list += (list.empty() ? "" : ", ") + std::to_string(a);
  }
  if (unit != nullptr && *unit != '\0') list += std::string(" ") + unit;
  return Status::fail(std::string("field '") + field + "' must be one of " + list + ", got " +
                      std::to_string(value));
}

Status check_photo_settings(uint8_t time_lapse_interval_s, uint8_t burst_count) {
  return first_failure(
      check_one_of("time_lapse_interval_s", time_lapse_interval_s, {5, 7, 30, 60}, "s"),
      check_one_of("burst_count", burst_count, {3, 5}));
}

Status check_time_of_day(int64_t hour, int64_t minute, int64_t second, int64_t millisecond) {
  return first_failure(check_int("hour", hour, 0, 23), check_int("minute", minute, 0, 59),
                       check_int("second", second, 0, 59),
                       check_int("millisecond", millisecond, 0, 999));
}

namespace {
bool parse_ipv4(const std::string& text, Ipv4Octets& out) {
  in_addr address{};
  if (inet_pton(AF_INET, text.c_str(), &address) != 1) return false;
  const uint32_t value = ntohl(address.s_addr);  // first octet in the most significant byte
  for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<uint8_t>(value >> (24 - 8 * i));
  return true;
}
}  // namespace

Status check_ipv4(const char* field, const std::string& text) {
  Ipv4Octets octets{};
  if (text.find('\0') == std::string::npos && parse_ipv4(text, octets)) return Status::ok();
  return Status::fail(std::string("field '") + field +
                      "' must be an IPv4 address like 192.168.144.64, got '" + text + "'");
}

Ipv4Octets ipv4_octets(const std::string& text) {
  Ipv4Octets octets{};
  if (!parse_ipv4(text, octets)) octets = {};
  return octets;
}

std::string ipv4_text(const Ipv4Octets& o) {
  return std::to_string(o[0]) + "." + std::to_string(o[1]) + "." + std::to_string(o[2]) + "." +
         std::to_string(o[3]);
}

uint32_t ipv4_value(const std::string& text) {
  const Ipv4Octets o = ipv4_octets(text);
  return static_cast<uint32_t>(o[0]) << 24 | static_cast<uint32_t>(o[1]) << 16 |
         static_cast<uint32_t>(o[2]) << 8 | o[3];
}

std::string ipv4_text(uint32_t value) {
  return ipv4_text(Ipv4Octets{static_cast<uint8_t>(value >> 24), static_cast<uint8_t>(value >> 16),
                              static_cast<uint8_t>(value >> 8), static_cast<uint8_t>(value)});
}

}  // namespace k40t::protocol::camera_codec
