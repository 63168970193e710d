#include "k40t_driver/sim/capture_writer.h"

#include <cerrno>
#include <cstring>

namespace k40t::sim {

Result<std::unique_ptr<CaptureWriter>> CaptureWriter::open(const std::string& prefix) {
  if (prefix.empty()) return Status::fail("capture: the file prefix is empty");
  const std::string tx_path = prefix + ".tx.bin";
  const std::string rx_path = prefix + ".rx.bin";
  std::FILE* tx = std::fopen(tx_path.c_str(), "wb");
  if (!tx) return Status::fail("capture: cannot create " + tx_path + ": " + std::strerror(errno));
  std::FILE* rx = std::fopen(rx_path.c_str(), "wb");
  if (!rx) {
    const std::string why = std::strerror(errno);
    std::fclose(tx);
    return Status::fail("capture: cannot create " + rx_path + ": " + why);
  }
  return std::unique_ptr<CaptureWriter>(new CaptureWriter(tx_path, tx, rx_path, rx));
}

CaptureWriter::CaptureWriter(std::string tx_path, std::FILE* tx, std::string rx_path, std::FILE* rx)
    : tx_path_(std::move(tx_path)), tx_(tx), rx_path_(std::move(rx_path)), rx_(rx) {}

CaptureWriter::~CaptureWriter() {
  std::fclose(tx_);
  std::fclose(rx_);
}

void CaptureWriter::write(std::FILE* file, const uint8_t* data, size_t size,
                          std::atomic<uint64_t>& counter) {
  std::lock_guard<std::mutex> lock(mutex_);
  counter += std::fwrite(data, 1, size, file);
  std::fflush(file);  // a killed simulator still leaves a complete capture
}

void CaptureWriter::sent(const uint8_t* data, size_t size) {
  write(tx_, data, size, bytes_sent_);
}
void CaptureWriter::received(const uint8_t* data, size_t size) {
  write(rx_, data, size, bytes_received_);
}

}  // namespace k40t::sim
