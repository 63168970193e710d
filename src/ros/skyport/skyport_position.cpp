// skyport/get_position (3.7.1): the rate limit (the document's 5 Hz at most, or the
// position_min_interval parameter), the 2 s window before the newest UTC push, fractional base
// times, event-index matching and solution 0 as no fix (position_request.h).
#include <cmath>

#include <ros/console.h>

#include "k40t_driver/ros/skyport/push_conversions.h"
#include "k40t_driver/ros/skyport/skyport_ros.h"
#include "k40t_driver/skyport/position_request.h"

namespace k40t::driver::skyport {

using namespace psdk;

bool SkyportRos::on_get_position(k40t_driver::GetPosition::Request& req,
                                 k40t_driver::GetPosition::Response& res) {
  std::lock_guard<std::mutex> one_at_a_time(position_mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (last_position_request_ &&
      std::chrono::duration<double>(now - *last_position_request_).count() <
          config_.position_min_interval_s) {
    res.message = "rate limit: at most one request per " +
                  std::to_string(config_.position_min_interval_s) + " s (3.7.1: 5 Hz at most)";
    return true;
  }
  std::optional<int64_t> newest;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    newest = newest_utc_ns_;
  }
  const Result<GetPosition> request = plan_position_request(
      static_cast<int64_t>(req.base_time.toNSec()), req.time_offsets_us, newest, next_event_index_);
  if (!request) {
    res.message = request.error();
    return true;
  }
  next_event_index_ =
      static_cast<uint16_t>((next_event_index_ + request->count) % kEventIndexCount);
  last_position_request_ = now;
  const Result<GetPositionAck> ack = session_->request(request.value());
  if (!ack) {
    res.message = ack.error();
    return true;
  }
  if (ack->code != AckCode::kOk) {
    res.message = "the adapter answered " + ack_code_text(static_cast<uint8_t>(ack->code));
    return true;
  }
  const auto matched = match_positions(request.value(), ack.value());
  size_t missing = 0;
  for (size_t i = 0; i < matched.size(); ++i) {
    const std::optional<TargetPosition>& p = matched[i];
    if (!p) ++missing;
    res.positions.push_back(
        position_fix(p, position_time_ns(request.value(), request->points[i].time_offset_us),
                     config_.world_frame));
    res.solutions.push_back(p ? static_cast<uint8_t>(p->solution) : 0);
  }
  res.success = missing == 0;
  res.message = missing == 0 ? "ok"
                             : std::to_string(missing) +
                                   " point(s) missing from the adapter's answer (by event index)";
  return true;
}

}  // namespace k40t::driver::skyport
