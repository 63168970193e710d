#include "k40t_driver/codec/layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace k40t::codec::detail {

namespace {
std::string hex_byte(uint8_t v) {
  char text[8];
  std::snprintf(text, sizeof(text), "0x%02X", static_cast<unsigned>(v));
  return text;
}
std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}
}  // namespace

std::string fixed_byte_error(size_t index, const wire::Fixed& fixed, uint8_t got) {
  if (fixed.decimal) {
    return "byte " + std::to_string(index) + " must be " + fixed.meaning + " " +
           std::to_string(fixed.value) + ", got " + std::to_string(got);
  }
  return "byte " + std::to_string(index) + " must be " + hex_byte(fixed.value) + " (" +
         fixed.meaning + "), got " + hex_byte(got);
}

std::string flag_error(const char* field, size_t index, const wire::Flag& flag, uint8_t got) {
  if (flag.decimal) {
    return "byte " + std::to_string(index) + " must be " + std::to_string(flag.off) + " (off) or " +
           std::to_string(flag.on) + " (on), got " + std::to_string(got);
  }
  return std::string("field '") + field + "' must be " + hex_byte(flag.on) + " (on) or " +
         hex_byte(flag.off) + " (off), got " + hex_byte(got);
}

std::string scale_error(const char* scale_name, int scale) {
  return std::string(scale_name) + " must be positive, got " + std::to_string(scale);
}

Status check_magnitude(const char* field, double value, const char* scale_name,
                       const wire::Limits& limits, int scale) {
  if (scale <= 0) return Status::fail(scale_error(scale_name, scale));
  constexpr double kMost = std::numeric_limits<uint16_t>::max();
  const double magnitude = std::round(std::fabs(value) * scale);
  if (magnitude <= kMost) return Status::ok();
  std::string why = std::string("field '") + field + "' " + number_text(value) + " x " +
                    scale_name + " " + std::to_string(scale) + " = " + number_text(magnitude) +
                    " does not fit the 16-bit magnitude (at most 65535)";
  if (limits.set) {
    const double widest = std::max(std::fabs(limits.lo), std::fabs(limits.hi));
    why += ": " + std::string(scale_name) + " must be 1.." +
           std::to_string(static_cast<int>(kMost / widest)) + " to carry the whole range";
  }
  return Status::fail(why);
}

std::string direction_error(const char* field, const wire::Code& positive,
                            const wire::Code& negative, uint8_t none, uint8_t got) {
  const bool positive_first = positive.value < negative.value;
  const wire::Code& first = positive_first ? positive : negative;
  const wire::Code& second = positive_first ? negative : positive;
  return std::string(field) + " direction byte must be " + std::to_string(first.value) + " (" +
         first.meaning + "), " + std::to_string(second.value) + " (" + second.meaning + ") or " +
         std::to_string(none) + " (no movement), got " + std::to_string(got);
}

}  // namespace k40t::codec::detail
