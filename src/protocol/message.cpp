#include "k40t_driver/protocol/message.h"

#include <cstdio>

namespace k40t::protocol {

const char* to_string(Direction direction) {
  return direction == Direction::kPodToHost ? "pod_to_host" : "host_to_pod";
}

Status payload_size_error(const char* name, MessageId id, size_t got, size_t min_size) {
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), "%s (0x%06X): payload of %zu bytes is too short, need %zu",
                name, static_cast<unsigned>(id), got, min_size);
  return Status::fail(buffer);
}

}  // namespace k40t::protocol
