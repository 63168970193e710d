#include "k40t_driver/skyport/version_text.h"

#include <cstdio>

namespace k40t::driver::skyport {

bool parse_version(const std::string& text, psdk::Version& out) {
  unsigned a = 0, b = 0, c = 0, d = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%u.%u.%u.%u%c", &a, &b, &c, &d, &tail) != 4) return false;
  if (a > 255 || b > 255 || c > 255 || d > 255) return false;
  out = psdk::Version{static_cast<uint8_t>(a), static_cast<uint8_t>(b), static_cast<uint8_t>(c),
                      static_cast<uint8_t>(d)};
  return true;
}

}  // namespace k40t::driver::skyport
