#include "k40t_driver/skyport/position_query.h"

namespace k40t::driver::skyport {

using namespace psdk;

void PositionQuery::synchronised(int64_t utc_ns) {
  std::lock_guard<std::mutex> lock(sync_mutex_);
  newest_utc_ns_ = utc_ns;
}

PositionAnswer PositionQuery::ask(int64_t base_ns, const std::vector<uint32_t>& offsets_us,
                                  Clock::time_point now) {
  std::lock_guard<std::mutex> one_at_a_time(ask_mutex_);
  PositionAnswer out;
  if (last_request_ &&
      std::chrono::duration<double>(now - *last_request_).count() < min_interval_s_) {
    out.message = "rate limit: at most one request per " + std::to_string(min_interval_s_) +
                  " s (3.7.1: 5 Hz at most)";
    return out;
  }
  std::optional<int64_t> newest;
  {
    std::lock_guard<std::mutex> lock(sync_mutex_);
    newest = newest_utc_ns_;
  }
  const Result<GetPosition> request =
      plan_position_request(base_ns, offsets_us, newest, next_event_index_);
  if (!request) {
    out.message = request.error();
    return out;
  }
  next_event_index_ =
      static_cast<uint16_t>((next_event_index_ + request->count) % kEventIndexCount);
  last_request_ = now;
  const Result<GetPositionAck> ack = session_.request(request.value());
  if (!ack) {
    out.message = ack.error();
    return out;
  }
  if (ack->code != AckCode::kOk) {
    out.message = "the adapter answered " + ack_code_text(static_cast<uint8_t>(ack->code));
    return out;
  }
  out.points = match_positions(request.value(), ack.value());
  size_t missing = 0;
  for (size_t i = 0; i < out.points.size(); ++i) {
    out.times_ns.push_back(position_time_ns(request.value(), request->points[i].time_offset_us));
    if (!out.points[i]) ++missing;
  }
  out.success = missing == 0;
  out.message = missing == 0 ? "ok"
                             : std::to_string(missing) +
                                   " point(s) missing from the adapter's answer (by event index)";
  return out;
}

}  // namespace k40t::driver::skyport
