#include "k40t_driver/sim/fault_injector.h"

#include <sstream>

#include "k40t_driver/protocol/frame.h"

namespace k40t::sim {

namespace {
constexpr size_t kSequenceOffset =
    4;  // SEQ byte of the frame header (docs/protocol/decisions.md#frame)
}

FaultInjector::FaultInjector(uint32_t seed, protocol::CrcCoverage coverage)
    : rng_(seed), coverage_(coverage) {}

FaultSettings FaultInjector::settings() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return settings_;
}

void FaultInjector::set_settings(const FaultSettings& settings) {
  std::lock_guard<std::mutex> lock(mutex_);
  settings_ = settings;
}

void FaultInjector::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  settings_ = FaultSettings{};
  silent_until_ = {};
}

void FaultInjector::jump_sequence(int frames) {
  std::lock_guard<std::mutex> lock(mutex_);
  sequence_offset_ = static_cast<uint8_t>(sequence_offset_ + frames);
  ++counters_.sequence_jumps;
}

void FaultInjector::silence_for(std::chrono::milliseconds duration, SteadyClock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  silent_until_ = now + duration;
}

bool FaultInjector::silenced(SteadyClock::time_point now) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return now < silent_until_;
}

void FaultInjector::set_coverage(protocol::CrcCoverage coverage) {
  std::lock_guard<std::mutex> lock(mutex_);
  coverage_ = coverage;
}

bool FaultInjector::chance(double probability) {
  if (probability <= 0) return false;
  if (probability >= 1) return true;
  return std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < probability;
}

void FaultInjector::renumber(std::vector<uint8_t>& frame) const {
  // Only whole frames are renumbered (the session writes one frame per send); anything else
  // passes through untouched.
  if (frame.size() < protocol::kFrameOverhead || frame[0] != protocol::kStx ||
      frame[1] + protocol::kFrameOverhead != frame.size()) {
    return;
  }
  frame[kSequenceOffset] = static_cast<uint8_t>(frame[kSequenceOffset] + sequence_offset_);
  const uint16_t crc = protocol::frame_checksum(frame.data(), frame.size(), coverage_);
  frame[frame.size() - 2] = static_cast<uint8_t>(crc & 0xFF);
  frame[frame.size() - 1] = static_cast<uint8_t>(crc >> 8);
}

std::vector<uint8_t> FaultInjector::outgoing(const uint8_t* data, size_t size,
                                             SteadyClock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (now < silent_until_) {
    ++counters_.frames_silenced;
    return {};
  }
  std::vector<uint8_t> frame(data, data + size);
  if (sequence_offset_ != 0) {
    renumber(frame);
    ++counters_.frames_renumbered;
  }
  std::vector<uint8_t> wire;
  if (chance(settings_.garbage_rate) && settings_.garbage_max_bytes > 0) {
    const size_t n = std::uniform_int_distribution<size_t>(1, settings_.garbage_max_bytes)(rng_);
    for (size_t i = 0; i < n; ++i) {
      uint8_t b = static_cast<uint8_t>(rng_());
      if (b == protocol::kStx) b = 0x00;
      wire.push_back(b);
    }
    ++counters_.garbage_bursts;
    counters_.garbage_bytes += n;
  }
  for (uint8_t b : frame) {
    if (chance(settings_.corrupt_rate)) {
      b ^= static_cast<uint8_t>(1u << (rng_() % 8));
      ++counters_.bytes_corrupted;
    }
    wire.push_back(b);
  }
  return wire;
}

bool FaultInjector::drop_ack() {
  std::lock_guard<std::mutex> lock(mutex_);
  const bool drop = chance(settings_.drop_ack_rate);
  if (drop) ++counters_.acks_dropped;
  return drop;
}

std::optional<uint16_t> FaultInjector::refusal(uint32_t request_id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (settings_.refuse_id == 0 || settings_.refuse_id != request_id) return std::nullopt;
  return settings_.refuse_code;
}

std::chrono::milliseconds FaultInjector::ack_delay() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (settings_.delay_ack_ms <= 0 || !chance(settings_.delay_ack_rate))
    return std::chrono::milliseconds(0);
  ++counters_.acks_delayed;
  return std::chrono::milliseconds(static_cast<int64_t>(settings_.delay_ack_ms));
}

void FaultInjector::count_disconnect() {
  std::lock_guard<std::mutex> lock(mutex_);
  ++counters_.disconnects;
}

FaultCounters FaultInjector::counters() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

std::string FaultInjector::describe() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::ostringstream out;
  out << "corrupt=" << settings_.corrupt_rate << " garbage=" << settings_.garbage_rate << "/"
      << settings_.garbage_max_bytes << " drop-acks=" << settings_.drop_ack_rate
      << " delay-acks=" << settings_.delay_ack_ms << "ms@" << settings_.delay_ack_rate
      << " refuse=" << settings_.refuse_id << "/" << settings_.refuse_code
      << " seq-offset=" << int{sequence_offset_}
      << " silenced=" << (SteadyClock::now() < silent_until_ ? 1 : 0)
      << " | corrupted=" << counters_.bytes_corrupted
      << " garbage-bursts=" << counters_.garbage_bursts
      << " acks-dropped=" << counters_.acks_dropped << " acks-delayed=" << counters_.acks_delayed
      << " seq-jumps=" << counters_.sequence_jumps
      << " silenced-frames=" << counters_.frames_silenced
      << " disconnects=" << counters_.disconnects;
  return out.str();
}

}  // namespace k40t::sim
