// skyport/get_position's logic, ROS-free (3.7.1): the rate limit (the document's 5 Hz at most, or
// the bridge's position_min_interval), the request planned against the newest synchronised UTC
// time (position_request.h), rolling event indices, the adapter asked and its answer matched by
// event index. One request at a time. The ROS glue turns the answer into NavSatFix messages
// (push_conversions.h's position_fix()).
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/psdk/session.h"
#include "k40t_driver/skyport/position_request.h"

namespace k40t::driver::skyport {

struct PositionAnswer {
  bool success = false;  // every point answered
  // "ok", why nothing was asked (rate limit, bad request, no UTC push yet), why the adapter did
  // not answer, or how many points its answer lacks.
  std::string message;
  // Per requested point, in order (empty when nothing was answered): its UTC instant and the
  // adapter's point with its event index, none when missing.
  std::vector<int64_t> times_ns;
  std::vector<std::optional<psdk::TargetPosition>> points;
};

class PositionQuery {
 public:
  using Clock = std::chrono::steady_clock;

  PositionQuery(psdk::Session& session, double min_interval_s)
      : session_(session), min_interval_s_(min_interval_s) {}

  // A UTC push was used: `utc_ns` is now the newest synchronised time.
  void synchronised(int64_t utc_ns);
  // The positions at base + offsets[i] (UTC ns, microseconds), asked of the adapter now.
  PositionAnswer ask(int64_t base_ns, const std::vector<uint32_t>& offsets_us,
                     Clock::time_point now);

 private:
  psdk::Session& session_;
  const double min_interval_s_;
  std::mutex sync_mutex_;
  std::optional<int64_t> newest_utc_ns_;
  std::mutex ask_mutex_;  // one request at a time (rate limit, event indices)
  std::optional<Clock::time_point> last_request_;
  uint16_t next_event_index_ = 0;
};

}  // namespace k40t::driver::skyport
