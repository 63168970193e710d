#include "k40t_driver/protocol/messages/camera_system.h"

#include <limits>

#include "camera_codec.h"

namespace k40t::protocol {

// ---- 0x00030E ------------------------------------------------------------------------------
Status TimeSyncRequest::extra_checks() const {
  return camera_codec::check_int("unix_time_ms", unix_time_ms, 0,
                                 std::numeric_limits<int64_t>::max(), "ms");
}

// ---- 0x000311 ------------------------------------------------------------------------------
Status SetIpRequest::extra_checks() const {
  const uint32_t inverted = ~ipv4_value(netmask);
  if ((inverted & (inverted + 1)) != 0) {  // not ones, then only zeros
    return Status::fail("field 'netmask' must be a contiguous netmask like 255.255.255.0, got '" +
                        netmask + "'");
  }
  if (mode == IpMode::kStatic && ipv4_value(address) == 0) {
    return Status::fail("field 'address' must not be 0.0.0.0 with mode 0 (static)");
  }
  return Status::ok();
}

// ---- ACK 0x010312 --------------------------------------------------------------------------
Status GetIpAck::finish_decode(size_t payload_size) const {
  return code_alone_or_at_least(kName, kId, payload_size, kSize);
}

// ---- ACK 0x010317 --------------------------------------------------------------------------
std::string CameraVersionAck::version_text() const {
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

Status CameraVersionAck::finish_decode(size_t payload_size) const {
  return code_alone_or_at_least(kName, kId, payload_size, kSize);
}

}  // namespace k40t::protocol
