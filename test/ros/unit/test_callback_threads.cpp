// ros/callback_threads.h: the standalone nodes' callback threads run callbacks concurrently, sleep
// while idle (AsyncSpinner's wake every 100 ms) and end as soon as their queue is disabled.
#include <dirent.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <future>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <ros/callback_queue.h>

#include "k40t_driver/ros/callback_threads.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver {
namespace {

using namespace std::chrono_literals;

// A callback that runs a function (ros::CallbackInterface's only duty).
class FunctionCallback : public ros::CallbackInterface {
 public:
  explicit FunctionCallback(std::function<void()> f) : f_(std::move(f)) {}
  CallResult call() override {
    f_();
    return Success;
  }

 private:
  std::function<void()> f_;
};

void post(ros::CallbackQueue& queue, std::function<void()> f) {
  queue.addCallback(boost::make_shared<FunctionCallback>(std::move(f)));
}

// Voluntary context switches (sleeps ended) of this process's threads named `name`, added up.
long wakeups_of(const std::string& name) {
  long total = 0;
  DIR* tasks = opendir("/proc/self/task");
  while (const dirent* task = readdir(tasks)) {
    const std::string dir = std::string("/proc/self/task/") + task->d_name;
    std::string comm;
    std::getline(std::ifstream(dir + "/comm"), comm);
    if (comm != name) continue;
    std::ifstream status(dir + "/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("voluntary_ctxt_switches:", 0) == 0) total += std::stol(line.substr(24));
  }
  closedir(tasks);
  return total;
}

TEST(CallbackThreads, RunCallbacksConcurrently) {
  ros::CallbackQueue queue;
  CallbackThreads threads(queue, 2);
  // Each callback waits for the other to start: both finish only on two threads at once.
  std::atomic<int> started{0};
  std::promise<void> both_done[2];
  for (int i = 0; i < 2; ++i) {
    post(queue, [&started, &done = both_done[i]] {
      ++started;
      const auto deadline = std::chrono::steady_clock::now() + 10s;
      while (started.load() < 2 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(1ms);
      done.set_value();
    });
  }
  for (std::promise<void>& done : both_done) done.get_future().wait();
  EXPECT_EQ(started.load(), 2);
  queue.disable();
}

TEST(CallbackThreads, SleepWhileIdle) {
  ros::CallbackQueue queue;
  std::unique_ptr<CallbackThreads> threads;
  {
    const transport::ThreadNameScope name("k40t_cb_idle");
    threads = std::make_unique<CallbackThreads>(queue, 4);
  }
  std::this_thread::sleep_for(200ms);  // started and waiting
  const long before = wakeups_of("k40t_cb_idle");
  std::this_thread::sleep_for(1500ms);
  const long wakeups = wakeups_of("k40t_cb_idle") - before;
  // Each looks again once a second at most: <= 2 each in 1.5 s. AsyncSpinner's wait of 100 ms
  // makes ~15 each.
  EXPECT_LE(wakeups, 8);
  queue.disable();
}

TEST(CallbackThreads, EndAsSoonAsTheQueueIsDisabled) {
  ros::CallbackQueue queue;
  CallbackThreads threads(queue, 4);
  std::this_thread::sleep_for(100ms);  // all four asleep in the queue
  queue.disable();
  std::future<void> ended = std::async(std::launch::async, [&threads] { threads.wait(); });
  // Woken by the queue, not by their next look a second later.
  EXPECT_EQ(ended.wait_for(500ms), std::future_status::ready);
}

}  // namespace
}  // namespace k40t::driver
