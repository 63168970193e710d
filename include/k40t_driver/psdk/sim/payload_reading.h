// How the simulated adapter reads the payload's answers where DJI's published PSDK 1.x headers
// and the protocol document disagree (docs/psdk.md P28..P30). Written from the two sources
// directly, byte by byte, with its own tables: not the payload's codec (psdk/commands/), so a
// layout that codec gets wrong is caught here instead of being agreed on.
#pragma once

#include <cstdint>
#include <string>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/psdk/frame.h"

namespace k40t::psdk::sim {

enum class PayloadReading : uint8_t { kDjiHeaders = 0, kDocument = 1 };
bool parse_payload_reading(const std::string& text, PayloadReading& out);  // dji_headers|document

// 3.5.1's ACK DATA (return code first).
struct GimbalStateReading {
  std::string mode;           // "free", "FPV", "following"
  uint8_t set_mode_code = 0;  // the same mode as 3.5.2's set command numbers it
  double pitch_deg = 0, roll_deg = 0, yaw_deg = 0;
};
Result<GimbalStateReading> read_gimbal_state(const Data& ack, PayloadReading reading);

// 3.4.9's ACK DATA.
struct SdCardReading {
  bool inserted = false, read_only = false, full = false, has_error = false;
  uint32_t total_mb = 0, free_mb = 0;
};
Result<SdCardReading> read_sd_card(const Data& ack, PayloadReading reading);

// 3.4.6's ACK DATA: the interval in seconds (uint8 in the document, uint16 in the headers).
struct ShootPhotoModeReading {
  uint8_t type = 0, burst_count = 0, interval_count = 0;
  uint16_t interval_s = 0;
};
Result<ShootPhotoModeReading> read_shoot_photo_mode(const Data& ack, PayloadReading reading);

}  // namespace k40t::psdk::sim
