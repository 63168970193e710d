#include "k40t_driver/psdk/command.h"

#include <cstdio>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::psdk {

const char* to_string(Sender sender) {
  return sender == Sender::kAdapter ? "adapter" : "payload";
}

const char* to_string(AckCode code) {
  return consecutive_name(code, 0, {"ok", "error", "unsupported"});
}

std::string ack_code_text(uint8_t code) {
  const char* text = consecutive_name(
      static_cast<AckCode>(code), 0,
      {"executed successfully", "executed unsuccessfully", "command not supported"});
  if (text != nullptr) return text;
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), "unknown return code 0x%02X", code);
  return buffer;
}

Status check_length(const char* field, size_t size, size_t lo, size_t hi) {
  if (size >= lo && size <= hi) return Status::ok();
  return Status::fail(std::string("field '") + field + "' must be " + std::to_string(lo) + ".." +
                      std::to_string(hi) + " bytes, got " + std::to_string(size));
}

std::string describe_size_error(const char* name, size_t got, size_t need) {
  return std::string(name) + ": DATA of " + std::to_string(got) + " bytes is too short, need " +
         std::to_string(need);
}

}  // namespace k40t::psdk
