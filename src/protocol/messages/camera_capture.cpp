#include "k40t_driver/protocol/messages/camera_capture.h"

#include "camera_codec.h"

namespace k40t::protocol {

// ---- 0x000301 and 0x000003 -----------------------------------------------------------------
Status PhotoSettings::extra_checks() const {
  return camera_codec::check_photo_settings(time_lapse_interval_s, burst_count);
}

}  // namespace k40t::protocol
