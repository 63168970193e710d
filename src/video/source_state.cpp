#include "k40t_driver/video/source_state.h"

#include <utility>

namespace k40t::video {

bool SourceState::pause(std::chrono::milliseconds delay) {
  std::unique_lock<std::mutex> lock(mutex);
  changed.wait_for(lock, delay, [this] { return !running; });
  return running;
}

bool SourceState::is_running() const {
  std::lock_guard<std::mutex> lock(mutex);
  return running;
}

bool SourceState::take_restart() {
  std::lock_guard<std::mutex> lock(mutex);
  return std::exchange(restart_requested, false);
}

void SourceState::request_restart() {
  std::lock_guard<std::mutex> lock(mutex);
  restart_requested = true;
}

void SourceState::failed(bool opened, const std::string& error) {
  std::lock_guard<std::mutex> lock(mutex);
  ++(opened ? stats.read_errors : stats.open_failures);
  stats.streaming = false;
  stats.last_error = error;
}

void SourceState::finish_thread() {
  std::lock_guard<std::mutex> lock(mutex);
  stats.streaming = false;
  exited = true;
  changed.notify_all();
}

void SourceState::stop(std::chrono::duration<double> grace) {
  std::unique_lock<std::mutex> lock(mutex);
  running = false;
  changed.notify_all();
  changed.wait_for(lock, grace, [this] { return exited; });
}

std::optional<GrabbedFrame> SourceState::wait_newer(uint64_t after,
                                                    std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex);
  changed.wait_for(lock, timeout, [&] { return !running || (latest && latest->sequence > after); });
  if (latest && latest->sequence > after) return latest;
  return std::nullopt;
}

GrabberStats SourceState::stats_now() const {
  std::lock_guard<std::mutex> lock(mutex);
  return stats;
}

}  // namespace k40t::video
