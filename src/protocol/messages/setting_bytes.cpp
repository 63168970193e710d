#include "setting_bytes.h"

#include <cstdio>
#include <string>

namespace k40t::protocol::detail {

namespace {
std::string hex_byte(uint8_t v) {
  char text[8];
  std::snprintf(text, sizeof(text), "0x%02X", static_cast<unsigned>(v));
  return text;
}
}  // namespace

Status expect_command_byte(ByteReader& r, uint8_t expected, const char* meaning) {
  const size_t index = r.position() + 1;  // the document counts bytes from 1
  const uint8_t got = r.u8();
  if (got == expected) return Status::ok();
  return Status::fail("byte " + std::to_string(index) + " must be " + hex_byte(expected) + " (" +
                      meaning + "), got " + hex_byte(got));
}

Status read_switch(ByteReader& r, const char* field, uint8_t on_code, uint8_t off_code, bool* on) {
  const uint8_t got = r.u8();
  if (got != on_code && got != off_code) {
    return Status::fail(std::string("field '") + field + "' must be " + hex_byte(on_code) +
                        " (on) or " + hex_byte(off_code) + " (off), got " + hex_byte(got));
  }
  *on = got == on_code;
  return Status::ok();
}

Status settings_follow(const ByteReader& r, ResponseCode code, size_t settings_size,
                       bool* has_settings) {
  *has_settings = r.remaining() > 0 || code == ResponseCode::kOk;
  if (!*has_settings || r.remaining() >= settings_size) return Status::ok();
  return Status::fail("the settings after the response code need " + std::to_string(settings_size) +
                      " bytes, got " + std::to_string(r.remaining()));
}

}  // namespace k40t::protocol::detail
