#include "k40t_driver/ros/callback_threads.h"

#include <pthread.h>

#include <csignal>

namespace k40t::driver {

namespace {

// How long an idle thread waits before it looks again: a callback or the queue's end wakes it
// sooner, so this bounds nothing a user sees; it only keeps a wake-up that never came (roscpp's
// queue loses none) from leaving a thread asleep for ever.
constexpr double kIdleWaitS = 1.0;

void call_until_disabled(ros::CallbackQueue& queue) {
  sigset_t all;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, nullptr);  // signals go to the main thread
  while (queue.callOne(ros::WallDuration(kIdleWaitS)) != ros::CallbackQueue::Disabled) {
  }
}

}  // namespace

CallbackThreads::CallbackThreads(ros::CallbackQueue& queue, int count) {
  for (int i = 0; i < count; ++i) threads_.emplace_back([&queue] { call_until_disabled(queue); });
}

CallbackThreads::~CallbackThreads() {
  wait();
}

void CallbackThreads::wait() {
  for (std::thread& thread : threads_)
    if (thread.joinable()) thread.join();
}

}  // namespace k40t::driver
