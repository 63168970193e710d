#include "setting_bytes.h"

#include <string>

namespace k40t::protocol::detail {

Status settings_follow(size_t payload_size, ResponseCode code, size_t settings_size) {
  constexpr size_t kCodeSize = 2;
  const size_t after_code = payload_size > kCodeSize ? payload_size - kCodeSize : 0;
  const bool has_settings = after_code > 0 || code == ResponseCode::kOk;
  if (!has_settings || after_code >= settings_size) return Status::ok();
  return Status::fail("the settings after the response code need " + std::to_string(settings_size) +
                      " bytes, got " + std::to_string(after_code));
}

}  // namespace k40t::protocol::detail
