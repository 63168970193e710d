// IPv4 addresses of the camera's IP messages (0x000311 and the ACK 0x010312): dotted-quad strings
// in the structs ("192.168.144.64"), four bytes on the wire, first octet first (section
// 3.2.4.16's example: mask 255 255 255 0). Each octet is a byte of its own, not a uint32, so the
// ACK byte order does not reverse them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "k40t_driver/protocol/result.h"

namespace k40t::protocol {

using Ipv4Octets = std::array<uint8_t, 4>;

// "field 'address' must be an IPv4 address like 192.168.144.64, got '192.168.1'"
Status check_ipv4(const char* field, const std::string& text);
Ipv4Octets ipv4_octets(const std::string& text);  // 0.0.0.0 for text check_ipv4 refuses
std::string ipv4_text(const Ipv4Octets& octets);
// As a 32-bit value whose most significant byte is the first octet.
uint32_t ipv4_value(const std::string& text);

// The wire format for a layout: v("address", s.address, wire::custom<Ipv4Field>) (codec/wire.h).
struct Ipv4Field {
  static constexpr size_t kSize = 4;
  template <class Out>
  static void write(Out& w, const std::string& text) {
    for (uint8_t octet : ipv4_octets(text)) w.u8(octet);
  }
  template <class In>
  static std::string read(In& r) {
    Ipv4Octets octets{};
    for (uint8_t& octet : octets) octet = r.u8();
    return ipv4_text(octets);
  }
  static Status check(const char* field, const std::string& text) {
    return check_ipv4(field, text);
  }
};

}  // namespace k40t::protocol
