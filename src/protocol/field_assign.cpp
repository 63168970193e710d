#include "k40t_driver/protocol/field_assign.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace k40t::protocol {

namespace {

std::string field_prefix(const char* name) {
  return std::string("field '") + name + "': ";
}

// strtoll/strtoull accept leading blanks and, for unsigned, a minus sign: reject both first.
bool plain_number_text(const std::string& text, bool allow_minus) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  return allow_minus || text[0] != '-';
}

// Decimal, or hex with 0x; never octal (a leading zero as in "08" means eight).
int base_of(const std::string& text) {
  const size_t digits = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  const bool hex = text.size() > digits + 1 && text[digits] == '0' &&
                   (text[digits + 1] == 'x' || text[digits + 1] == 'X');
  return hex ? 16 : 10;
}

}  // namespace

bool looks_numeric(const std::string& text) {
  if (text.empty()) return false;
  const char c = text[0];
  return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
}

Result<int64_t> parse_signed_field(const char* name, const std::string& text, int64_t lo,
                                   int64_t hi) {
  const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
  if (!plain_number_text(text, true)) {
    return Result<int64_t>::fail(field_prefix(name) + "expected an integer " + range + ", got '" +
                                 text + "'");
  }
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, base_of(text));
  if (end == text.c_str() || *end != '\0') {
    return Result<int64_t>::fail(field_prefix(name) + "expected an integer " + range + ", got '" +
                                 text + "'");
  }
  if (errno == ERANGE || value < lo || value > hi) {
    return Result<int64_t>::fail(field_prefix(name) + "must be " + range + ", got " + text);
  }
  return static_cast<int64_t>(value);
}

Result<uint64_t> parse_unsigned_field(const char* name, const std::string& text, uint64_t hi) {
  const std::string range = "0.." + std::to_string(hi);
  if (!plain_number_text(text, false)) {
    const bool negative = !text.empty() && text[0] == '-';
    return Result<uint64_t>::fail(field_prefix(name) +
                                  (negative ? "must be " : "expected an integer ") + range +
                                  ", got " + (negative ? text : "'" + text + "'"));
  }
  errno = 0;
  char* end = nullptr;
  const unsigned long long value = std::strtoull(text.c_str(), &end, base_of(text));
  if (end == text.c_str() || *end != '\0') {
    return Result<uint64_t>::fail(field_prefix(name) + "expected an integer " + range + ", got '" +
                                  text + "'");
  }
  if (errno == ERANGE || value > hi) {
    return Result<uint64_t>::fail(field_prefix(name) + "must be " + range + ", got " + text);
  }
  return static_cast<uint64_t>(value);
}

Result<double> parse_real_field(const char* name, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double value = text.empty() || std::isspace(static_cast<unsigned char>(text[0]))
                           ? 0.0
                           : std::strtod(text.c_str(), &end);
  if (end == nullptr || end == text.c_str() || *end != '\0' || !std::isfinite(value) ||
      errno == ERANGE) {
    return Result<double>::fail(field_prefix(name) + "expected a finite number, got '" + text +
                                "'");
  }
  return value;
}

Result<bool> parse_bool_field(const char* name, const std::string& text) {
  if (text == "1" || text == "true") return true;
  if (text == "0" || text == "false") return false;
  return Result<bool>::fail(field_prefix(name) + "expected 0, 1, true or false, got '" + text +
                            "'");
}

Status parse_bytes_field(const char* name, const std::string& text, uint8_t* out, size_t count) {
  const std::string expected = "expected " + std::to_string(count) +
                               " numbers 0..255 separated by ',' or '.', got '" + text + "'";
  size_t n = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t next = text.find_first_of(",.", pos);
    if (next == std::string::npos) next = text.size();
    const std::string item = text.substr(pos, next - pos);
    Result<uint64_t> value = parse_unsigned_field(name, item, 0xFF);
    if (!value || n == count) return Status::fail(field_prefix(name) + expected);
    out[n++] = static_cast<uint8_t>(value.value());
    pos = next + 1;
  }
  if (n != count) return Status::fail(field_prefix(name) + expected);
  return Status::ok();
}

std::string normalize_label(const std::string& label) {
  std::string out;
  bool pending_separator = false;
  for (char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      if (pending_separator && !out.empty()) out += '_';
      pending_separator = false;
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else {
      pending_separator = true;
    }
  }
  return out;
}

std::string unknown_fields_error(const char* message, const std::vector<std::string>& unknown,
                                 const std::vector<std::string>& fields) {
  std::string text = std::string(message) + " has no field";
  text += unknown.size() == 1 ? " " : "s ";
  for (size_t i = 0; i < unknown.size(); ++i) text += (i ? ", '" : "'") + unknown[i] + "'";
  text += "; its fields: ";
  if (fields.empty()) text += "(none)";
  for (size_t i = 0; i < fields.size(); ++i) text += (i ? ", " : "") + fields[i];
  return text;
}

}  // namespace k40t::protocol
