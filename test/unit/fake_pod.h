// A scripted pod for tests of PodDriver without the simulator: it owns the pty (the driver opens
// its symlink as serial://), records every frame the driver sends, answers each request with an
// OK ACK (unless told not to), and sends what the test asks for.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/parser.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::driver::testing {

struct SentFrame {
  protocol::MessageId id = 0;
  std::vector<uint8_t> payload;
  std::chrono::steady_clock::time_point at;
};

class FakePod {
 public:
  explicit FakePod(const std::string& path) {
    Result<std::unique_ptr<transport::Transport>> pty = transport::make_transport("pty://" + path);
    EXPECT_TRUE(pty.is_ok()) << pty.error();
    pty_ = std::move(pty.value());
    pty_->set_receive_callback([this](const uint8_t* data, size_t size) { on_bytes(data, size); });
    const Status opened = pty_->open();
    EXPECT_TRUE(opened.is_ok()) << opened.message();
  }
  ~FakePod() { pty_->close(); }

  void set_auto_ack(bool on) { auto_ack_ = on; }

  // Sends `message` as the pod would (from the camera address).
  template <class Msg>
  void send(const Msg& message) {
    Result<protocol::Payload> payload = protocol::encode_payload(message);
    ASSERT_TRUE(payload.is_ok()) << payload.error();
    send_raw(Msg::kId, payload->data(), payload->size);
  }
  void send_raw(protocol::MessageId id, const uint8_t* payload, size_t size) {
    protocol::FrameHeader header;
    header.destination = protocol::kHostAddress;
    header.source = protocol::kCameraAddress;
    header.sequence = sequence_++;
    header.message_id = id;
    Result<protocol::EncodedFrame> frame =
        protocol::encode_frame(header, payload, size, protocol::CrcCoverage::kHeaderExcluded);
    ASSERT_TRUE(frame.is_ok()) << frame.error();
    // The driver opens the pty in the background: retry until it is there.
    for (int attempt = 0; attempt < 100; ++attempt) {
      if (pty_->send(frame->data(), frame->size()).is_ok()) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ADD_FAILURE() << "the fake pod could not send";
  }

  // Waits until `predicate(frames)` holds; returns a copy of the frames received so far.
  std::vector<SentFrame> wait_for(
      const std::function<bool(const std::vector<SentFrame>&)>& predicate,
      std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    arrived_.wait_for(lock, timeout, [&] { return predicate(frames_); });
    return frames_;
  }
  std::vector<SentFrame> frames_with_id(protocol::MessageId id) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<SentFrame> out;
    for (const SentFrame& f : frames_)
      if (f.id == id) out.push_back(f);
    return out;
  }
  static auto count_of(protocol::MessageId id, size_t n) {
    return [id, n](const std::vector<SentFrame>& frames) {
      size_t count = 0;
      for (const SentFrame& f : frames) count += f.id == id;
      return count >= n;
    };
  }

 private:
  void on_bytes(const uint8_t* data, size_t size) {
    parser_.feed(data, size, [this](const protocol::FrameView& frame) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        frames_.push_back({frame.header.message_id,
                           std::vector<uint8_t>(frame.payload, frame.payload + frame.payload_size),
                           std::chrono::steady_clock::now()});
      }
      arrived_.notify_all();
      if (auto_ack_ &&
          protocol::kind_of(frame.header.message_id) == protocol::MessageKind::kRequestOrReport) {
        const uint8_t ok[2] = {0, 0};
        send_raw(protocol::ack_id_of(frame.header.message_id), ok, sizeof ok);
      }
    });
  }

  std::unique_ptr<transport::Transport> pty_;
  protocol::FrameParser parser_{protocol::CrcCoverage::kHeaderExcluded};
  uint8_t sequence_ = 0;
  bool auto_ack_ = true;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<SentFrame> frames_;
};

}  // namespace k40t::driver::testing
