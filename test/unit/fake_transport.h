// An in-memory Transport pair for session tests: what one end sends, the other receives on its
// own delivery thread (like a real transport's I/O thread). Tests can inject bytes as if they
// came off the wire, make sends fail, and read back everything an end wrote.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "k40t_driver/transport/transport.h"

namespace k40t::test {

class FakeTransport : public transport::Transport {
 public:
  struct Wire;  // the two ends, guarded by its mutex so that either end may go away first

  FakeTransport(std::string name, std::shared_ptr<Wire> wire, int end);
  ~FakeTransport() override;

  // Two ends joined by a wire. The returned raw pointers stay valid while the owners live (the
  // sessions own the transports; tests keep the raw pointers to inject or inspect).
  static std::pair<std::unique_ptr<FakeTransport>, std::unique_ptr<FakeTransport>> pair();

  Status open() override;
  void close() override;
  Status send(const uint8_t* data, size_t size) override;
  transport::LinkState state() const override;
  transport::LinkStats stats() const override;
  std::string url() const override { return "fake://" + name_; }

  // Delivers bytes to this end's receive callback as if they had arrived from the peer.
  void inject(std::vector<uint8_t> bytes);
  // While set, send() fails with a message naming this end, and writes nothing.
  void fail_sends(bool fail);
  // Everything this end wrote successfully, concatenated.
  std::vector<uint8_t> written() const;

 private:
  void run();
  void deliver(const uint8_t* data, size_t size);  // from the peer's send()

  const std::string name_;
  const std::shared_ptr<Wire> wire_;
  const int end_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::vector<uint8_t>> inbox_;
  bool open_ = false;
  bool stopping_ = false;
  bool fail_sends_ = false;
  std::vector<uint8_t> written_;
  transport::LinkStats stats_;
  std::thread thread_;
};

}  // namespace k40t::test
