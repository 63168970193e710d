// sbus/set as one operation over two requests (0x000500 value range, 0x000501 channel map,
// section 3.2.6): both validated before either is sent, and if the pod refuses the second after
// accepting the first, the previous range (read with 0x000502 beforehand) is written back. The
// outcome says exactly what the pod now holds; both take effect only after a power cycle
// (sections 3.2.6.1 and 3.2.6.2 notes).
#pragma once

#include <string>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/messages/sbus.h"

namespace k40t::driver {

struct SbusWriteOutcome {
  bool success = false;  // both applied
  bool range_applied = false;
  bool channels_applied = false;
  bool power_cycle_needed = false;  // the pod holds something new
  std::string message;
};

SbusWriteOutcome write_sbus(PodDriver& driver, const protocol::SbusRangeRequest& range,
                            const protocol::SbusChannelsRequest& channels);

}  // namespace k40t::driver
