// One background thread that runs the panel's service calls in order, so that a call waiting for
// the pod (ACK timeouts and retries: up to about a second) never freezes the Qt GUI thread.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace k40t::rviz_panel {

class ServiceWorker {
 public:
  ServiceWorker();
  // Drops the jobs not started yet and joins the thread: waits at most for the call in progress.
  ~ServiceWorker();
  ServiceWorker(const ServiceWorker&) = delete;
  ServiceWorker& operator=(const ServiceWorker&) = delete;

  void post(std::function<void()> job);

 private:
  void run();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace k40t::rviz_panel
