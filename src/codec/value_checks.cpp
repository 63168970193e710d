#include "k40t_driver/codec/value_checks.h"

#include <sstream>

namespace k40t::codec {

namespace {
std::string format_real(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}
std::string with_unit(const std::string& value, const char* unit) {
  return unit && *unit ? value + " " + unit : value;
}
}  // namespace

Status check_range(const char* field, int64_t value, int64_t lo, int64_t hi, const char* unit) {
  if (value >= lo && value <= hi) return Status::ok();
  return Status::fail(std::string("field '") + field + "' must be " + std::to_string(lo) + ".." +
                      with_unit(std::to_string(hi), unit) + ", got " + std::to_string(value));
}

Status check_range(const char* field, double value, double lo, double hi, const char* unit) {
  if (value >= lo && value <= hi) return Status::ok();  // also rejects NaN
  return Status::fail(std::string("field '") + field + "' must be " + format_real(lo) + ".." +
                      with_unit(format_real(hi), unit) + ", got " + format_real(value));
}

Status check_text(const char* field, const std::string& value, size_t max_bytes) {
  if (value.size() > max_bytes) {
    return Status::fail(std::string("field '") + field + "' must be at most " +
                        std::to_string(max_bytes) + " bytes, got " + std::to_string(value.size()));
  }
  if (value.find('\0') != std::string::npos) {
    return Status::fail(std::string("field '") + field + "' must not contain NUL bytes");
  }
  return Status::ok();
}

std::string describe_allowed_codes(const char* field, int64_t value, const std::string& allowed) {
  return std::string("field '") + field + "' has no code " + std::to_string(value) +
         "; allowed: " + allowed;
}

}  // namespace k40t::codec
