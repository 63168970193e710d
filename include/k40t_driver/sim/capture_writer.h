// Records every byte the simulated pod sends and receives, exactly as on the wire (faults
// included), to two raw files: PREFIX.tx.bin (pod -> host) and PREFIX.rx.bin (host -> pod). Each
// is a plain byte stream, the format `k40t decode FILE` and `k40t monitor FILE` read; the two
// directions are kept apart because received bytes arrive in arbitrary chunks, and interleaving
// them with sent frames would cut frames in two.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>

#include "k40t_driver/protocol/result.h"

namespace k40t::sim {

class CaptureWriter {
 public:
  // Creates (truncates) both files; fails naming the file that cannot be opened.
  static Result<std::unique_ptr<CaptureWriter>> open(const std::string& prefix);
  ~CaptureWriter();
  CaptureWriter(const CaptureWriter&) = delete;
  CaptureWriter& operator=(const CaptureWriter&) = delete;

  void sent(const uint8_t* data, size_t size);
  void received(const uint8_t* data, size_t size);

  const std::string& tx_path() const { return tx_path_; }
  const std::string& rx_path() const { return rx_path_; }
  uint64_t bytes_sent() const { return bytes_sent_; }
  uint64_t bytes_received() const { return bytes_received_; }

 private:
  CaptureWriter(std::string tx_path, std::FILE* tx, std::string rx_path, std::FILE* rx);
  void write(std::FILE* file, const uint8_t* data, size_t size, std::atomic<uint64_t>& counter);

  std::mutex mutex_;  // one write at a time; the counters are read without it
  std::string tx_path_;
  std::FILE* tx_;
  std::string rx_path_;
  std::FILE* rx_;
  std::atomic<uint64_t> bytes_sent_{0};
  std::atomic<uint64_t> bytes_received_{0};
};

}  // namespace k40t::sim
