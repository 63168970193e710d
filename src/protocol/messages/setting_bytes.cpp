#include "setting_bytes.h"

#include <string>

#include "k40t_driver/codec/layout_detail.h"

namespace k40t::protocol::detail {

Status expect_command_byte(ByteReader& r, uint8_t expected, const char* meaning) {
  const size_t index = r.position() + 1;  // the document counts bytes from 1
  const uint8_t got = r.u8();
  if (got == expected) return Status::ok();
  return Status::fail(
      codec::detail::fixed_byte_error(index, codec::wire::fixed(expected, meaning), got));
}

Status read_switch(ByteReader& r, const char* field, uint8_t on_code, uint8_t off_code, bool* on) {
  const size_t index = r.position() + 1;
  const uint8_t got = r.u8();
  if (got != on_code && got != off_code) {
    return Status::fail(
        codec::detail::flag_error(field, index, codec::wire::flag(on_code, off_code), got));
  }
  *on = got == on_code;
  return Status::ok();
}

Status settings_follow(size_t after_code, ResponseCode code, size_t settings_size,
                       bool* has_settings) {
  *has_settings = after_code > 0 || code == ResponseCode::kOk;
  if (!*has_settings || after_code >= settings_size) return Status::ok();
  return Status::fail("the settings after the response code need " + std::to_string(settings_size) +
                      " bytes, got " + std::to_string(after_code));
}

}  // namespace k40t::protocol::detail
