// The conformance rig: a k40t_sim PodServer on a pseudo-terminal and a client built only on the
// core library (a Session over the serial transport, opened on the pty's symlink) — the same
// pieces the driver uses. The client keeps every frame it receives, answers the pod's GPS
// requests as a flight controller would, and waits for conditions with a deadline (never a
// fixed sleep where a condition can be waited for).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "eventually.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/session/session.h"
#include "k40t_driver/sim/pod_server.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::sim::testing {

using namespace std::chrono_literals;

// Waits give up after the tests' generous deadline: only a broken pod reaches it, and simulated
// time follows the wall clock while the threads that send and count frames may wait for a CPU.
constexpr std::chrono::milliseconds kWaitDeadline = test::kEventuallyDeadline;

// A pty path no other test (or test run) uses.
inline std::string unique_pty_path() {
  static std::atomic<int> counter{0};
  return "/tmp/k40t_sim_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
}

// The flight controller's answer to the pod's 0x000310.
constexpr double kHostLatitudeDeg = 47.3977;
constexpr double kHostLongitudeDeg = 8.5456;
constexpr double kHostAltitudeM = 488.0;

class SimLink {
 public:
  explicit SimLink(SimOptions sim = {}, session::SessionOptions client = {}) {
    path_ = unique_pty_path();
    sim.link = "pty://" + path_;
    server_ = std::make_unique<PodServer>(sim);
    const Status started = server_->start();
    EXPECT_TRUE(started) << started.message();

    auto transport = transport::make_transport("serial://" + path_ + "?baud=115200");
    EXPECT_TRUE(transport) << transport.error();
    client_ = std::make_unique<session::Session>(std::move(transport).value(), client);
    client_->dispatcher().on_frame([this](const protocol::FrameView& f) {
      std::lock_guard<std::mutex> lock(mutex_);
      frames_[f.header.message_id].emplace_back(f.payload, f.payload + f.payload_size);
    });
    client_->set_request_handler(protocol::CameraGpsRequest::kId,
                                 [this](const protocol::FrameView& f) { return answer_gps(f); });
    const Status opened = client_->start();
    EXPECT_TRUE(opened) << opened.message();
    EXPECT_TRUE(wait_for([&] { return count(protocol::GimbalAttitude::kId) > 0; }))
        << "no attitude report from the simulator on " << path_;
  }

  ~SimLink() {
    client_->stop();
    server_->stop();
  }

  PodServer& server() { return *server_; }
  session::Session& client() { return *client_; }
  const protocol::CodecOptions& codec() const { return client_->options().codec; }

  template <class Req>
  protocol::ResponseCode send(const Req& request) {
    const session::AckResult result = client_->request(request);
    EXPECT_TRUE(result.sent) << Req::kName << ": " << result.message;
    return result.received ? result.code : protocol::ResponseCode::kTimeout;
  }
  template <class Req>
  typename Req::Ack ask(const Req& request) {
    auto ack = client_->request_typed(request);
    EXPECT_TRUE(ack) << Req::kName << ": " << ack.error();
    return ack ? *ack : typename Req::Ack{};
  }
  // Raw bytes (out-of-range values a typed struct would refuse to encode).
  protocol::ResponseCode send_raw(protocol::MessageId id, const std::vector<uint8_t>& payload) {
    const session::AckResult result = client_->request_raw(id, payload.data(), payload.size());
    return result.received ? result.code : protocol::ResponseCode::kTimeout;
  }

  size_t count(protocol::MessageId id) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = frames_.find(id);
    return it == frames_.end() ? 0 : it->second.size();
  }

  template <class Msg>
  std::vector<Msg> all() const {
    std::vector<Msg> out;
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = frames_.find(Msg::kId);
    if (it == frames_.end()) return out;
    for (const auto& payload : it->second) {
      auto decoded =
          protocol::decode_payload<Msg>(payload.data(), payload.size(), client_->options().codec);
      if (decoded) out.push_back(*decoded);
    }
    return out;
  }

  template <class Msg>
  std::optional<Msg> latest() const {
    const auto messages = all<Msg>();
    if (messages.empty()) return std::nullopt;
    return messages.back();
  }

  // How many frames of each id have been received so far: take one before a request whose answer
  // is a one-shot report, and wait for the report received since. The report can overtake the
  // ACK's return to the caller (a loaded machine), so counting from after the request misses it.
  using Mark = std::map<protocol::MessageId, size_t>;
  Mark mark() const {
    std::lock_guard<std::mutex> lock(mutex_);
    Mark counts;
    for (const auto& [id, frames] : frames_) counts[id] = frames.size();
    return counts;
  }

  // Waits until a report `Msg` received from now on satisfies `condition`; returns it. Only for
  // reports that repeat (periodic ones); one-shot reports use the overload with a Mark.
  template <class Msg>
  std::optional<Msg> wait_report(const std::function<bool(const Msg&)>& condition,
                                 std::chrono::milliseconds timeout = kWaitDeadline) {
    return wait_report<Msg>(mark(), condition, timeout);
  }

  // Waits until a report `Msg` received since `since` satisfies `condition`; returns it.
  template <class Msg>
  std::optional<Msg> wait_report(const Mark& since,
                                 const std::function<bool(const Msg&)>& condition,
                                 std::chrono::milliseconds timeout = kWaitDeadline) {
    const auto it = since.find(Msg::kId);
    const size_t seen = it == since.end() ? 0 : it->second;
    std::optional<Msg> found;
    wait_for(
        [&] {
          const auto messages = all<Msg>();
          for (size_t i = seen; i < messages.size(); ++i) {
            if (condition(messages[i])) {
              found = messages[i];
              return true;
            }
          }
          return false;
        },
        timeout);
    return found;
  }

  static bool wait_for(const std::function<bool()>& condition,
                       std::chrono::milliseconds timeout = kWaitDeadline) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      if (condition()) return true;
      std::this_thread::sleep_for(10ms);
    }
    return condition();
  }

  int gps_answers() const { return gps_answers_; }
  const std::string& path() const { return path_; }

 private:
  std::optional<protocol::Payload> answer_gps(const protocol::FrameView& frame) {
    auto request =
        protocol::decode_payload<protocol::CameraGpsRequest>(frame, client_->options().codec);
    if (!request) return std::nullopt;
    auto ack = protocol::CameraGpsAck::answering(*request);
    ack.latitude_deg = kHostLatitudeDeg;
    ack.longitude_deg = kHostLongitudeDeg;
    ack.altitude_m = kHostAltitudeM;
    ack.relative_height_m = 30;
    ++gps_answers_;
    auto payload = protocol::encode_payload(ack, client_->options().codec);
    if (!payload) return std::nullopt;
    return *payload;
  }

  std::string path_;
  std::unique_ptr<PodServer> server_;
  std::unique_ptr<session::Session> client_;
  mutable std::mutex mutex_;
  std::map<protocol::MessageId, std::vector<std::vector<uint8_t>>> frames_;
  std::atomic<int> gps_answers_{0};
};

}  // namespace k40t::sim::testing
