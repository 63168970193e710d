// Which requests may be sent again when their ACK is late. The document gives no ACK latency and
// ACKs carry no sequence number (docs/protocol/decisions.md#a5), and the pod asks for GPS before
// it shoots (section 3.2.4.3), so an ACK later than ack_timeout is likely for a photo; the session
// repeats a request whose ACK is late (retries), which for most requests (settings, moves to an
// angle, read-backs) does no harm. For these, a repeat repeats an action: a second photo, a
// second zoom step, a recording stopped or started again. They are sent once and waited for as long
// as all the attempts would have taken (docs/session.md#requests-sent-once):
//   0x000302 take photo, 0x000303 record, 0x000307 precise re-shoot (a photo too),
//   0x000306 with code 3 / 4 (one zoom step in / out; the continuous codes are states),
//   0x000013, 0x00002E, 0x000031 gimbal calibrations (a repeat starts the calibration again; a
//   pod whose calibrations end with their ACK answers only when done: done_ack_wait()).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>

#include "k40t_driver/protocol/convention_values.h"
#include "k40t_driver/protocol/message_id.h"

namespace k40t::protocol {

// False for a request whose repeat would repeat its action (the list above).
bool repeat_safe(MessageId id, const uint8_t* payload, size_t size);

// The longest calibration the driver waits an ACK for (the document gives no duration).
constexpr std::chrono::milliseconds kCalibrationAckWait{60000};

// How long a request sent once may wait for its ACK when the pod answers it only once the action
// is done: the calibrations under calibration_end ack, and auto until the pod shows which
// (docs/protocol/decisions.md#conventions). Zero for every other request: the usual wait.
std::chrono::milliseconds done_ack_wait(MessageId id, const Conventions& conventions);

}  // namespace k40t::protocol
