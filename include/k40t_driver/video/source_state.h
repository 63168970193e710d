// What both frame sources (frame_grabber.h, access_unit_source.h) share: the life of their reading
// thread (started detached, so that a thread left blocked in the back-end after stop() still has
// valid state to return to; stopped with a grace period; sleeping between reconnects), the
// newest decoded frame that wait_newer() hands out, and the counters.
#pragma once

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "k40t_driver/video/frame_source.h"

namespace k40t::video {

struct SourceState {
  mutable std::mutex mutex;
  std::condition_variable changed;
  bool running = false;
  bool exited = true;
  bool restart_requested = false;
  std::optional<GrabbedFrame> latest;
  GrabberStats stats;

  // Sleeps up to `delay` unless stopped; false once stopped.
  bool pause(std::chrono::milliseconds delay);
  bool is_running() const;
  // True once per request_restart() call.
  bool take_restart();
  void request_restart();
  // A failed open (`opened` false) or a stream that ended.
  void failed(bool opened, const std::string& error);
  // The thread's last act.
  void finish_thread();
  // Ends the thread, waiting up to `grace` for it.
  void stop(std::chrono::duration<double> grace);
  std::optional<GrabbedFrame> wait_newer(uint64_t after, std::chrono::milliseconds timeout);
  GrabberStats stats_now() const;
};

// Runs state->run() on a detached thread that shares `state`, unless one is running.
template <class State>
void start_source_thread(const std::shared_ptr<State>& state) {
  std::lock_guard<std::mutex> lock(state->mutex);
  if (state->running || !state->exited) return;
  state->running = true;
  state->exited = false;
  std::thread([state] { state->run(); }).detach();
}

}  // namespace k40t::video
