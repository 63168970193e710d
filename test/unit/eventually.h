// Waiting in tests: poll a condition until it holds or a generous deadline passes. The deadline is
// only reached when something is broken; tests never assert on elapsed time.
#pragma once

#include <chrono>
#include <functional>
#include <thread>

namespace k40t::test {

constexpr std::chrono::seconds kEventuallyDeadline{15};

// Polls `condition` until it holds or `deadline` passes; returns whether it held.
inline bool eventually(const std::function<bool()>& condition,
                       std::chrono::steady_clock::duration deadline = kEventuallyDeadline) {
  const auto until = std::chrono::steady_clock::now() + deadline;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

}  // namespace k40t::test
