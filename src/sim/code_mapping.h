// Model enums carry the document's numbers (events.h, camera_settings.h, sd_card.h...), like the
// protocol's enums do; crossing between the two is a change of type, not of value.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <type_traits>

#include "k40t_driver/sim/pod_model.h"

namespace k40t::sim::handlers {

template <class To, class From>
To same_code(From value) {
  static_assert(std::is_enum_v<To> || std::is_integral_v<To>, "a code type");
  using FromInt =
      std::conditional_t<std::is_enum_v<From>, std::underlying_type<From>, std::common_type<From>>;
  return static_cast<To>(static_cast<typename FromInt::type>(value));
}

// Dotted quad <-> octets (first octet first). The protocol structs validated the text already.
Ipv4 parse_ipv4(const std::string& text);
std::string format_ipv4(const Ipv4& address);

}  // namespace k40t::sim::handlers
