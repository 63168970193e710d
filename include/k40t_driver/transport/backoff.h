// The delay sequence between reconnection attempts: initial, initial*factor, ... capped at max,
// back to initial after a success.
#pragma once

#include <chrono>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::transport {

// Rejects policies that would spin (zero delay) or shrink (factor < 1).
Status check_policy(const ReconnectPolicy& policy);

class Backoff {
 public:
  explicit Backoff(const ReconnectPolicy& policy) : policy_(policy), next_(policy.initial_delay) {}

  // The delay to wait now; the following call returns the next step.
  std::chrono::milliseconds next();
  void reset() { next_ = policy_.initial_delay; }

 private:
  ReconnectPolicy policy_;
  std::chrono::milliseconds next_;
};

}  // namespace k40t::transport
