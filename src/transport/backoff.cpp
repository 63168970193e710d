#include "k40t_driver/transport/backoff.h"

#include <algorithm>
#include <string>

namespace k40t::transport {

Status check_policy(const ReconnectPolicy& policy) {
  if (policy.initial_delay.count() <= 0) {
    return Status::fail("reconnect policy: initial_delay must be positive, not " +
                        std::to_string(policy.initial_delay.count()) + " ms");
  }
  if (policy.max_delay < policy.initial_delay) {
    return Status::fail("reconnect policy: max_delay (" + std::to_string(policy.max_delay.count()) +
                        " ms) is below initial_delay (" +
                        std::to_string(policy.initial_delay.count()) + " ms)");
  }
  if (!(policy.factor >= 1.0)) {  // also catches NaN
    return Status::fail("reconnect policy: factor must be >= 1, not " +
                        std::to_string(policy.factor));
  }
  return Status::ok();
}

std::chrono::milliseconds Backoff::next() {
  const auto now = next_;
  const double grown = static_cast<double>(next_.count()) * policy_.factor;
  const double capped = std::min(grown, static_cast<double>(policy_.max_delay.count()));
  next_ = std::chrono::milliseconds(static_cast<long long>(capped));
  return now;
}

}  // namespace k40t::transport
