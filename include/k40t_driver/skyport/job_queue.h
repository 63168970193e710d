// The SKYPORT bridge's worker: one thread running jobs (pod calls) in order from a bounded queue.
// The session's handlers must not block its I/O thread, so whatever needs the pod is queued here;
// a full queue refuses the job at once (the caller answers "busy"), so a pod outage under DJI
// Pilot's polling cannot grow memory without limit. ROS-free.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace k40t::driver::skyport {

class JobQueue {
 public:
  explicit JobQueue(size_t capacity);
  ~JobQueue();  // stop()s
  JobQueue(const JobQueue&) = delete;
  JobQueue& operator=(const JobQueue&) = delete;

  // Queues `job`; false when the queue holds `capacity` jobs already or is stopping.
  bool push(std::function<void()> job);
  // Jobs waiting (not counting the one running).
  size_t depth() const;
  size_t capacity() const { return capacity_; }
  // Drops the waiting jobs and joins the worker once the running job returns. Idempotent.
  void stop();

 private:
  void run();

  const size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::thread worker_;
};

}  // namespace k40t::driver::skyport
