// skyport/get_position (3.7.1): the ROS-free PositionQuery asks the adapter (rate limit, the 2 s
// window before the newest UTC push, fractional base times, event-index matching); each point
// becomes a NavSatFix, solution 0 no fix (push_conversions.h).
#include "k40t_driver/ros/skyport/push_conversions.h"
#include "k40t_driver/ros/skyport/skyport_ros.h"

namespace k40t::driver::skyport {

bool SkyportRos::on_get_position(k40t_driver::GetPosition::Request& req,
                                 k40t_driver::GetPosition::Response& res) {
  const PositionAnswer answer = positions_.ask(static_cast<int64_t>(req.base_time.toNSec()),
                                               req.time_offsets_us, PositionQuery::Clock::now());
  for (size_t i = 0; i < answer.points.size(); ++i) {
    const std::optional<psdk::TargetPosition>& p = answer.points[i];
    res.positions.push_back(position_fix(p, answer.times_ns[i], config_.world_frame));
    res.solutions.push_back(p ? static_cast<uint8_t>(p->solution) : 0);
  }
  res.success = answer.success;
  res.message = answer.message;
  return true;
}

}  // namespace k40t::driver::skyport
