#include "fault_schedule.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace k40t::skyport_sim {

FaultSchedule::FaultSchedule(psdk::sim::AdapterSimulator& adapter,
                             std::vector<sim::ScheduledFault> faults)
    : adapter_(adapter), faults_(std::move(faults)) {
  std::sort(faults_.begin(), faults_.end(),
            [](const sim::ScheduledFault& a, const sim::ScheduledFault& b) { return a.at < b.at; });
  if (!faults_.empty()) thread_ = std::thread([this] { run(); });
}

FaultSchedule::~FaultSchedule() {
  stop();
}

void FaultSchedule::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void FaultSchedule::run() {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_);
  for (const sim::ScheduledFault& fault : faults_) {
    if (wake_.wait_until(lock, start + fault.at, [this] { return stopping_; })) return;
    const auto duration = std::chrono::milliseconds(std::llround(fault.amount * 1000));
    switch (fault.kind) {
      case sim::ScheduledFault::Kind::kSilence:
        adapter_.silence_for(duration);
        break;
      case sim::ScheduledFault::Kind::kDisconnect:
        adapter_.disconnect_for(duration);
        break;
      case sim::ScheduledFault::Kind::kSequenceJump:
        adapter_.jump_sequence(static_cast<uint16_t>(fault.amount));
        break;
    }
  }
}

}  // namespace k40t::skyport_sim
