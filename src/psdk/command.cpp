#include "k40t_driver/psdk/command.h"

#include <cstdio>

namespace k40t::psdk {

const char* to_string(Sender sender) {
  return sender == Sender::kAdapter ? "adapter" : "payload";
}

const char* to_string(AckCode code) {
  switch (code) {
    case AckCode::kOk:
      return "ok";
    case AckCode::kError:
      return "error";
    case AckCode::kUnsupported:
      return "unsupported";
  }
  return nullptr;
}

std::string ack_code_text(uint8_t code) {
  switch (static_cast<AckCode>(code)) {
    case AckCode::kOk:
      return "executed successfully";
    case AckCode::kError:
      return "executed unsuccessfully";
    case AckCode::kUnsupported:
      return "command not supported";
  }
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
