// The protocol core of `skyport_sim`: a simulated DJI SKYPORT adapter on the other end of the
// payload's UART. It runs the adapter role of a psdk::Session:
//   - identity verification with a known app key, at start and then every `identity_interval`;
//   - the data pushes of set 0x03 at realistic rates, from one consistent flight (FlightModel),
//     the battery push asking for an ACK (and announcing power-off when told to);
//   - answers to the payload's own commands: get-position (0x07/0x01) from the flight, and it
//     records floating-window messages and transparent data;
//   - scripted camera, gimbal and payload-state exchanges that check every ACK (CheckReport);
//   - fault options: byte corruption, garbage between frames, silence (FaultyTransport), dropped
//     and delayed ACKs and sequence jumps (here).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/psdk/session.h"
#include "k40t_driver/psdk/sim/check_report.h"
#include "k40t_driver/psdk/sim/faulty_transport.h"
#include "k40t_driver/psdk/sim/flight_model.h"
#include "k40t_driver/psdk/sim/payload_reading.h"
#include "k40t_driver/psdk/sim/pushes.h"

namespace k40t::psdk::sim {

// Named like k40t_sim's FaultSettings.
struct ProtocolFaults {
  double drop_ack_rate = 0.0;       // probability that a payload command gets no ACK from us
  double delay_ack_ms = 0.0;        // our ACKs go out this late...
  double delay_ack_rate = 1.0;      // ...with this probability
  double sequence_jump_rate = 0.0;  // per command: skip 1..100 sequence numbers
};

struct AdapterOptions {
  // What the payload is registered with. The app key proves identity; all four make the AES
  // key. Never logged.
  Credentials credentials;
  bool encryption = true;  // derive the AES key and read/write encrypted frames
  FlightModelOptions flight;
  PushRates rates;
  uint8_t gps_satellites = 14;
  std::chrono::milliseconds identity_interval{30000};
  std::chrono::milliseconds ack_timeout{500};
  ByteFaults byte_faults;
  ProtocolFaults protocol_faults;
  uint32_t seed = 1;  // random bytes of identity verification, fault dice
  // How the checks read the payload's answers where DJI's headers and the document disagree.
  PayloadReading reading = PayloadReading::kDjiHeaders;
};

struct IdentityResult {
  bool answered = false;  // an ACK came back
  bool passed = false;    // ... and it proved the app key
  std::string detail;
};

struct AdapterStats {
  std::map<std::string, uint64_t> pushes_sent;  // by command name
  uint64_t identity_passed = 0;
  uint64_t identity_failed = 0;  // wrong digest, refusal or no answer
  uint64_t battery_acks = 0;
  bool last_power_off_ready = false;
  uint64_t positions_answered = 0;
  uint64_t acks_dropped = 0;
  uint64_t acks_delayed = 0;
  uint64_t sequence_jumps = 0;
  uint64_t transparent_to_mobile_bytes = 0;
  uint64_t transparent_to_onboard_bytes = 0;
  SessionStats session;
  ByteFaultStats byte_faults;
};

class AdapterSimulator {
 public:
  AdapterSimulator(std::unique_ptr<transport::Transport> transport, AdapterOptions options);
  ~AdapterSimulator();  // stop()s
  AdapterSimulator(const AdapterSimulator&) = delete;
  AdapterSimulator& operator=(const AdapterSimulator&) = delete;

  // Opens the link and starts pushing; the first identity verification runs at once.
  Status start();
  void stop();

  // One identity verification now (blocking; not from a session handler).
  IdentityResult verify_identity();
  // Version, hand-shake echo, product information, alias, SKYPORT version.
  CheckReport check_payload_state();
  CheckReport check_camera();
  CheckReport check_gimbal();
  // A command the document does not define must come back 0x02.
  CheckReport check_unsupported();

  // Fault switches, while running (read them to change one and keep the others).
  ByteFaults byte_faults() const;
  ProtocolFaults protocol_faults() const;
  void set_byte_faults(const ByteFaults& faults);
  void set_protocol_faults(const ProtocolFaults& faults);
  void silence_for(std::chrono::milliseconds duration);
  // Closes the link and reopens it after `duration` (the worker thread reopens it).
  void disconnect_for(std::chrono::milliseconds duration);
  // Our following commands skip `count` sequence numbers (one gap).
  void jump_sequence(uint16_t count);
  // The next UTC push (3.3.10) goes out `delay` after its turn, with the same content: a push
  // late for its PPS edge, which the payload must drop when over 500 ms.
  void delay_next_utc_push(std::chrono::milliseconds delay);
  // From now on the battery push announces power-off (and asks the payload to get ready).
  void announce_power_off();

  AdapterStats stats() const;
  std::vector<std::string> floating_window_messages() const;
  // The flight's state now (what the pushes are built from).
  AirframeState airframe_now() const;
  Session& session() { return *session_; }

 private:
  void run();
  void send_due_pushes(double t_s);
  void push_or_delay_utc(const UtcTimePush& message);
  void send_late_utc_push();
  void check_interval_mode(CheckReport& report);  // part of check_camera()
  template <class Push>
  void push(const Push& message);
  void maybe_jump_sequence();
  std::optional<Data> answer_get_position(const IncomingCommand& in);
  void send_later(const FrameHeader& header, const Data& data);
  void flush_delayed_acks();
  bool roll(double probability);
  double elapsed_s() const;

  AdapterOptions options_;
  FlightModel flight_;
  FaultyTransport* faulty_ = nullptr;  // owned by session_
  std::unique_ptr<Session> session_;

  mutable std::mutex mutex_;  // everything below
  std::mt19937 random_;
  ProtocolFaults protocol_faults_;
  AdapterStats stats_;
  std::vector<std::string> floating_window_;
  std::optional<double> power_off_from_s_;
  uint16_t raw_gps_counter_ = 0;
  std::optional<std::chrono::milliseconds> utc_delay_;  // for the next UTC push
  struct LateUtcPush {
    std::chrono::steady_clock::time_point due;
    UtcTimePush push;
  };
  std::optional<LateUtcPush> late_utc_;
  struct DelayedAck {
    std::chrono::steady_clock::time_point due;
    FrameHeader header;
    Data data;
  };
  std::deque<DelayedAck> delayed_;

  struct Schedule {
    const char* name;
    double hz;
    double next_s;
  };
  std::vector<Schedule> schedule_;  // worker thread only
  double next_identity_s_ = 0;

  std::chrono::steady_clock::time_point start_time_;
  std::thread worker_;
  std::mutex wake_mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::atomic<bool> started_{false};
};

}  // namespace k40t::psdk::sim
