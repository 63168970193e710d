#include "k40t_driver/psdk/sim/faulty_transport.h"

#include <algorithm>
#include <vector>

namespace k40t::psdk::sim {

FaultyTransport::FaultyTransport(std::unique_ptr<transport::Transport> inner, ByteFaults faults)
    : inner_(std::move(inner)), faults_(faults), random_(faults.seed) {}

Status FaultyTransport::open() {
  inner_->set_receive_callback(on_receive_);
  inner_->set_state_callback(on_state_);
  inner_->set_reconnect_policy(policy_);
  return inner_->open();
}

void FaultyTransport::close() {
  inner_->close();
}

ByteFaults FaultyTransport::faults() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return faults_;
}

void FaultyTransport::set_faults(const ByteFaults& faults) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (faults.seed != faults_.seed) random_.seed(faults.seed);
  faults_ = faults;
}

void FaultyTransport::silence_for(std::chrono::milliseconds duration) {
  std::lock_guard<std::mutex> lock(mutex_);
  silent_until_ = std::chrono::steady_clock::now() + duration;
}

void FaultyTransport::disconnect_for(std::chrono::milliseconds duration) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (disconnected_) return;
    disconnected_ = true;
    reopen_at_ = std::chrono::steady_clock::now() + duration;
    ++stats_.disconnects;
  }
  inner_->close();  // outside the lock: the I/O thread may be sending while it is joined
}

void FaultyTransport::poll() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!disconnected_ || std::chrono::steady_clock::now() < reopen_at_) return;
    disconnected_ = false;
  }
  (void)inner_->open();  // a device that is absent now is retried by the transport itself
}

ByteFaultStats FaultyTransport::fault_stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

Status FaultyTransport::send(const uint8_t* data, size_t size) {
  std::vector<uint8_t> out;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.writes;
    if (disconnected_) return Status::fail(inner_->url() + ": disconnected (simulated fault)");
    if (std::chrono::steady_clock::now() < silent_until_) {
      ++stats_.writes_silenced;
      return Status::ok();
    }
    std::uniform_real_distribution<double> chance(0.0, 1.0);
    std::uniform_int_distribution<int> byte(0, 255);
    if (faults_.garbage_rate > 0 && chance(random_) < faults_.garbage_rate) {
      const int n = std::uniform_int_distribution<int>(
          1, static_cast<int>(std::max<size_t>(faults_.garbage_max_bytes, 1)))(random_);
      for (int i = 0; i < n; ++i) out.push_back(static_cast<uint8_t>(byte(random_)));
      ++stats_.garbage_bursts;
      stats_.garbage_bytes += static_cast<uint64_t>(n);
    }
    const size_t start = out.size();
    out.insert(out.end(), data, data + size);
    if (faults_.corrupt_rate > 0) {
      for (size_t i = start; i < out.size(); ++i) {
        if (chance(random_) < faults_.corrupt_rate) {
          out[i] = static_cast<uint8_t>(out[i] ^
                                        (1u << std::uniform_int_distribution<int>(0, 7)(random_)));
          ++stats_.bytes_corrupted;
        }
      }
    }
  }
  return inner_->send(out.data(), out.size());
}

}  // namespace k40t::psdk::sim
