#include "k40t_driver/psdk/pending_requests.h"

#include <algorithm>

namespace k40t::psdk {

void PendingRequests::add(CommandKey key, uint16_t sequence, Clock::time_point deadline,
                          Callback done) {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.push_back({key, sequence, deadline, std::move(done)});
}

void PendingRequests::cancel(CommandKey key, uint16_t sequence) {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.erase(
      std::remove_if(entries_.begin(), entries_.end(),
                     [&](const Entry& e) { return e.key == key && e.sequence == sequence; }),
      entries_.end());
}

std::optional<PendingRequests::Callback> PendingRequests::take(CommandKey key, uint16_t sequence) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = std::find_if(entries_.begin(), entries_.end(),
                         [&](const Entry& e) { return e.key == key && e.sequence == sequence; });
  if (it == entries_.end()) return std::nullopt;
  Callback done = std::move(it->done);
  entries_.erase(it);
  return done;
}

std::vector<PendingRequests::Expired> PendingRequests::take_expired(Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Expired> out;
  auto keep = std::stable_partition(entries_.begin(), entries_.end(),
                                    [&](const Entry& e) { return e.deadline > now; });
  for (auto it = keep; it != entries_.end(); ++it)
    out.push_back({it->key, it->sequence, std::move(it->done)});
  entries_.erase(keep, entries_.end());
  return out;
}

std::vector<PendingRequests::Expired> PendingRequests::take_all() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Expired> out;
  for (Entry& e : entries_) out.push_back({e.key, e.sequence, std::move(e.done)});
  entries_.clear();
  return out;
}

std::optional<PendingRequests::Clock::time_point> PendingRequests::next_deadline() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (entries_.empty()) return std::nullopt;
  return std::min_element(entries_.begin(), entries_.end(),
                          [](const Entry& a, const Entry& b) { return a.deadline < b.deadline; })
      ->deadline;
}

size_t PendingRequests::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

}  // namespace k40t::psdk
