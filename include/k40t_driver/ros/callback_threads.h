// The threads a standalone node runs its callbacks on: roscpp's AsyncSpinner, except that an idle
// thread sleeps until a callback arrives instead of waking every 100 ms to look at its stop flag
// (AsyncSpinner's fixed timeout: 40 wake-ups a second for four idle threads, about a tenth of
// the driver's CPU at full telemetry). The queue wakes one waiting thread for each callback it is
// given and all of them when it is disabled, which ros::shutdown() does to the global queue: the
// threads end then, at once.
#pragma once

#include <thread>
#include <vector>

#include <ros/callback_queue.h>

namespace k40t::driver {

class CallbackThreads {
 public:
  // `count` threads calling `queue`'s callbacks one at a time each (concurrently, like
  // AsyncSpinner with more than one thread). They inherit the creating thread's name
  // (transport/thread_name.h) and, like AsyncSpinner's, take no signals.
  CallbackThreads(ros::CallbackQueue& queue, int count);
  ~CallbackThreads();  // waits for the threads: disable the queue first
  CallbackThreads(const CallbackThreads&) = delete;
  CallbackThreads& operator=(const CallbackThreads&) = delete;

  // Returns once every thread has ended, i.e. once the queue is disabled.
  void wait();

 private:
  std::vector<std::thread> threads_;
};

}  // namespace k40t::driver
