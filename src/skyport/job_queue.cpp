#include "k40t_driver/skyport/job_queue.h"

#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver::skyport {

JobQueue::JobQueue(size_t capacity) : capacity_(capacity) {
  worker_ = std::thread([this] { run(); });
}

JobQueue::~JobQueue() {
  stop();
}

bool JobQueue::push(std::function<void()> job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_ || jobs_.size() >= capacity_) return false;
    jobs_.push_back(std::move(job));
  }
  wake_.notify_one();
  return true;
}

size_t JobQueue::depth() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return jobs_.size();
}

void JobQueue::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    jobs_.clear();
  }
  wake_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void JobQueue::run() {
  transport::name_this_thread("k40t_sky_job");
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
    if (stopping_) return;
    std::function<void()> job = std::move(jobs_.front());
    jobs_.pop_front();
    lock.unlock();
    job();
    lock.lock();
  }
}

}  // namespace k40t::driver::skyport
