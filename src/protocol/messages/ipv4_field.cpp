#include "k40t_driver/protocol/messages/ipv4_field.h"

#include <arpa/inet.h>

namespace k40t::protocol {

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

}  // namespace k40t::protocol
