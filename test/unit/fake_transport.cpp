#include "fake_transport.h"

namespace k40t::test {

struct FakeTransport::Wire {
  std::mutex mutex;
  FakeTransport* ends[2] = {nullptr, nullptr};
};

FakeTransport::FakeTransport(std::string name, std::shared_ptr<Wire> wire, int end)
    : name_(std::move(name)), wire_(std::move(wire)), end_(end) {
  std::lock_guard<std::mutex> lock(wire_->mutex);
  wire_->ends[end_] = this;
}

FakeTransport::~FakeTransport() {
  {
    std::lock_guard<std::mutex> lock(wire_->mutex);
    wire_->ends[end_] = nullptr;
  }
  close();
}

std::pair<std::unique_ptr<FakeTransport>, std::unique_ptr<FakeTransport>> FakeTransport::pair() {
  auto wire = std::make_shared<Wire>();
  return {std::make_unique<FakeTransport>("host", wire, 0),
          std::make_unique<FakeTransport>("pod", wire, 1)};
}

Status FakeTransport::open() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (open_) return Status::fail(url() + ": already open");
    open_ = true;
    stopping_ = false;
    ++stats_.connects;
  }
  thread_ = std::thread([this] { run(); });
  return Status::ok();
}

void FakeTransport::close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!open_) return;
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  open_ = false;
  inbox_.clear();
}

void FakeTransport::run() {
  if (on_state_) on_state_(transport::LinkState::kConnected, "fake link up");
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || !inbox_.empty(); });
    if (stopping_) break;
    std::vector<uint8_t> chunk = std::move(inbox_.front());
    inbox_.pop_front();
    ++stats_.reads;
    stats_.bytes_received += chunk.size();
    lock.unlock();
    if (on_receive_) on_receive_(chunk.data(), chunk.size());
    lock.lock();
  }
}

Status FakeTransport::send(const uint8_t* data, size_t size) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!open_) return Status::fail(url() + ": not open");
    if (fail_sends_) {
      ++stats_.send_errors;
      stats_.last_error = url() + ": write failed (test fault)";
      return Status::fail(stats_.last_error);
    }
    written_.insert(written_.end(), data, data + size);
    ++stats_.writes;
    stats_.bytes_sent += size;
  }
  std::lock_guard<std::mutex> wire_lock(wire_->mutex);
  if (FakeTransport* peer = wire_->ends[1 - end_]) peer->deliver(data, size);
  return Status::ok();
}

void FakeTransport::deliver(const uint8_t* data, size_t size) {
  inject(std::vector<uint8_t>(data, data + size));
}

void FakeTransport::inject(std::vector<uint8_t> bytes) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!open_ || stopping_) return;  // nobody listening: the bytes are lost, as on a wire
    inbox_.push_back(std::move(bytes));
  }
  wake_.notify_all();
}

void FakeTransport::fail_sends(bool fail) {
  std::lock_guard<std::mutex> lock(mutex_);
  fail_sends_ = fail;
}

std::vector<uint8_t> FakeTransport::written() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return written_;
}

transport::LinkState FakeTransport::state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return open_ ? transport::LinkState::kConnected : transport::LinkState::kClosed;
}

transport::LinkStats FakeTransport::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

}  // namespace k40t::test
