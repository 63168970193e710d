// skyport/get_position's request and answer, ROS-free (3.7.1). Times are UTC nanoseconds.
//   - The date-time field holds whole seconds only: the base time's fraction moves into each
//     point's offset, so every point asks for exactly the instant the caller gave.
//   - Every instant must lie within the 2 s before the newest synchronised timestamp (the latest
//     UTC push) and not after it; the adapter's answer would be worthless otherwise.
//   - Each point carries its own event index (a rolling counter), and the answer's points are
//     matched by it, not by their order.
//   - Solution 0 ("not available") is no fix.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/psdk/commands/positioning.h"

namespace k40t::driver::skyport {

constexpr int64_t kPositionWindowNs = 2'000'000'000;  // 3.7.1's note
constexpr uint16_t kEventIndexCount = 8192;           // 13 bits

// The request for the instants base + offsets[i]; `newest_sync_ns` is the newest synchronised UTC
// timestamp (none yet: refused). Event indices start at `first_event_index` (mod 8192).
Result<psdk::GetPosition> plan_position_request(int64_t base_ns,
                                                const std::vector<uint32_t>& offsets_us,
                                                std::optional<int64_t> newest_sync_ns,
                                                uint16_t first_event_index);

// Seconds since 1970 of a PSDK date-time (UTC).
int64_t unix_seconds(const psdk::DateTime& t);

// The UTC instant of `point`, whose offset counts from the request's whole-second base time.
int64_t position_time_ns(const psdk::GetPosition& request, uint32_t time_offset_us);

// For each requested point in order, the answered point with its event index (none if missing).
std::vector<std::optional<psdk::TargetPosition>> match_positions(const psdk::GetPosition& request,
                                                                 const psdk::GetPositionAck& ack);

// Whether the solution is a position at all (0, "not available", is not).
inline bool is_fix(psdk::PositionSolution solution) {
  return solution != psdk::PositionSolution::kNotAvailable;
}

}  // namespace k40t::driver::skyport
