#include "k40t_driver/psdk/sim/adapter_simulator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "k40t_driver/psdk/sim/adapter_table.h"

namespace k40t::psdk::sim {
namespace {

SessionOptions session_options(const AdapterOptions& o) {
  SessionOptions s;
  s.role = Sender::kAdapter;
  s.ack_timeout = o.ack_timeout;
  if (o.encryption) s.aes_key = derive_aes_key(o.credentials);
  return s;
}

std::unique_ptr<transport::Transport> wrap(std::unique_ptr<transport::Transport> inner,
                                           const ByteFaults& faults, FaultyTransport** raw) {
  auto faulty = std::make_unique<FaultyTransport>(std::move(inner), faults);
  *raw = faulty.get();
  return faulty;
}

}  // namespace

AdapterSimulator::AdapterSimulator(std::unique_ptr<transport::Transport> transport,
                                   AdapterOptions options)
    : options_(std::move(options)),
      flight_(options_.flight),
      session_(std::make_unique<Session>(wrap(std::move(transport), options_.byte_faults, &faulty_),
                                         session_options(options_))),
      random_(options_.seed),
      protocol_faults_(options_.protocol_faults) {
  const PushRates& r = options_.rates;
  schedule_ = {{AttitudePush::kName, r.attitude_hz, 0},
               {GpsPush::kName, r.gps_hz, 0},
               {RawGpsPush::kName, r.raw_gps_hz, 0},
               {RawRtkPush::kName, r.raw_rtk_hz, 0},
               {BarometricAltitudePush::kName, r.barometric_altitude_hz, 0},
               {BatteryInfoPush::kName, r.battery_hz, 0},
               {UavStatePush::kName, r.uav_state_hz, 0},
               {LinkBandwidthPush::kName, r.link_bandwidth_hz, 0},
               {AppDateTimePush::kName, r.app_date_time_hz, 0},
               {UtcTimePush::kName, r.utc_time_hz, 0},
               {OtherPayloadTypePush::kName, r.other_payload_hz, 0}};

  session_->on_command(GetPosition::key(),
                       [this](const IncomingCommand& in) { return answer_get_position(in); });
  session_->on_command(FloatingWindowMessage::key(),
                       [this](const IncomingCommand& in) -> std::optional<Data> {
                         // 3.2.3: UTF-8 text ending with a NUL (read up to it, as the
                         // adapter's own reading: adapter_table.h).
                         const char* text = reinterpret_cast<const char*>(in.data.data());
                         std::lock_guard<std::mutex> lock(mutex_);
                         if (in.data.size > 0)
                           floating_window_.emplace_back(text, strnlen(text, in.data.size));
                         return std::nullopt;
                       });
  session_->on_command(TransparentToMobile::key(),
                       [this](const IncomingCommand& in) -> std::optional<Data> {
                         std::lock_guard<std::mutex> lock(mutex_);
                         stats_.transparent_to_mobile_bytes += in.data.size;
                         return std::nullopt;
                       });
  session_->on_command(TransparentToOnboard::key(),
                       [this](const IncomingCommand& in) -> std::optional<Data> {
                         std::lock_guard<std::mutex> lock(mutex_);
                         stats_.transparent_to_onboard_bytes += in.data.size;
                         return std::nullopt;
                       });
}

AdapterSimulator::~AdapterSimulator() {
  stop();
}

Status AdapterSimulator::start() {
  if (started_) return Status::ok();
  const Status s = session_->start();
  if (!s) return s;
  start_time_ = std::chrono::steady_clock::now();
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    stopping_ = false;
  }
  started_ = true;
  worker_ = std::thread([this] { run(); });
  return Status::ok();
}

void AdapterSimulator::stop() {
  if (!started_.exchange(false)) return;
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  worker_.join();
  session_->stop();
}

double AdapterSimulator::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time_).count();
}

AirframeState AdapterSimulator::airframe_now() const {
  AirframeState s = flight_.state_at(elapsed_s());
  std::lock_guard<std::mutex> lock(mutex_);
  if (power_off_from_s_ && s.t_s >= *power_off_from_s_) s.power_off_soon = true;
  return s;
}

bool AdapterSimulator::roll(double probability) {
  if (probability <= 0) return false;
  return std::uniform_real_distribution<double>(0.0, 1.0)(random_) < probability;
}

// --- the worker: pushes, periodic identity verification, delayed ACKs
// -----------------------------

void AdapterSimulator::run() {
  std::unique_lock<std::mutex> lock(wake_mutex_);
  while (!stopping_) {
    lock.unlock();
    const double t = elapsed_s();
    if (t >= next_identity_s_) {
      verify_identity();
      next_identity_s_ =
          elapsed_s() + std::chrono::duration<double>(options_.identity_interval).count();
    }
    faulty_->poll();  // reopen the link after a simulated disconnect
    send_due_pushes(elapsed_s());
    flush_delayed_acks();
    lock.lock();
    // 2 ms granularity is finer than the fastest push (50 Hz).
    wake_.wait_for(lock, std::chrono::milliseconds(2), [this] { return stopping_; });
  }
}

void AdapterSimulator::delay_next_utc_push(std::chrono::milliseconds delay) {
  std::lock_guard<std::mutex> lock(mutex_);
  utc_delay_ = delay;
}

void AdapterSimulator::push_or_delay_utc(const UtcTimePush& message) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (utc_delay_) {
      late_utc_ = LateUtcPush{std::chrono::steady_clock::now() + *utc_delay_, message};
      utc_delay_.reset();
      return;
    }
  }
  push(message);
}

void AdapterSimulator::send_late_utc_push() {
  std::optional<UtcTimePush> due;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (late_utc_ && std::chrono::steady_clock::now() >= late_utc_->due) {
      due = late_utc_->push;
      late_utc_.reset();
    }
  }
  if (due) push(*due);
}

void AdapterSimulator::send_due_pushes(double t_s) {
  send_late_utc_push();
  const AirframeState s = airframe_now();
  for (Schedule& item : schedule_) {
    if (item.hz <= 0 || t_s < item.next_s) continue;
    const double period = 1.0 / item.hz;
    // Keep the cadence; after a stall, start again from now rather than bursting.
    item.next_s = t_s - item.next_s > period ? t_s + period : item.next_s + period;
    const std::string name = item.name;
    if (name == AttitudePush::kName)
      push(attitude_push(s));
    else if (name == GpsPush::kName)
      push(gps_push(s, options_.gps_satellites));
    else if (name == RawRtkPush::kName)
      push(raw_rtk_push(s));
    else if (name == BarometricAltitudePush::kName)
      push(barometric_altitude_push(s));
    else if (name == UavStatePush::kName)
      push(uav_state_push(s, options_.flight.drone_type));
    else if (name == LinkBandwidthPush::kName)
      push(link_bandwidth_push(s));
    else if (name == AppDateTimePush::kName)
      push(app_date_time_push(s));
    else if (name == UtcTimePush::kName)
      push_or_delay_utc(utc_time_push(s));
    else if (name == OtherPayloadTypePush::kName)
      push(OtherPayloadTypePush{});
    else if (name == RawGpsPush::kName) {
      uint16_t counter = 0;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        counter = raw_gps_counter_++;
      }
      push(raw_gps_push(s, counter));
    } else if (name == BatteryInfoPush::kName) {
      push(battery_push(s));
    }
  }
}

void AdapterSimulator::maybe_jump_sequence() {
  uint16_t jump = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!roll(protocol_faults_.sequence_jump_rate)) return;
    jump = static_cast<uint16_t>(std::uniform_int_distribution<int>(1, 100)(random_));
    ++stats_.sequence_jumps;
  }
  session_->skip_sequence(jump);
}

template <class Push>
void AdapterSimulator::push(const Push& message) {
  maybe_jump_sequence();
  Status sent = Status::ok();
  if constexpr (std::is_same_v<Push, BatteryInfoPush>) {
    // The battery push asks for an ACK: its second byte tells whether the payload is ready for
    // power-off (read only while power-off is announced).
    const Result<Data> data = encode_data(message);
    if (!data) return;
    session_->request_async(Push::key(), data.value(), [this](const AckResult& r) {
      if (!r.received) return;
      const Result<table::Reading> ack = table::read(Push::key(), r.data);  // the adapter's table
      std::lock_guard<std::mutex> lock(mutex_);
      ++stats_.battery_acks;
      if (ack) stats_.last_power_off_ready = ack->number("power_off_ready") == 1;
    });
  } else {
    sent = session_->send(message);
  }
  if (!sent) return;
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.pushes_sent[Push::kName];
}

// --- the payload's commands: answer_get_position() in adapter_positioning.cpp -------------------

void AdapterSimulator::flush_delayed_acks() {
  std::vector<DelayedAck> due;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    while (!delayed_.empty() && delayed_.front().due <= now) {
      due.push_back(delayed_.front());
      delayed_.pop_front();
    }
  }
  for (const DelayedAck& d : due) session_->send_ack(d.header, d.data);
}

// --- identity verification -----------------------------------------------------------------------

IdentityResult AdapterSimulator::verify_identity() {
  // 3.1.1: 16 random bytes; the ACK is the code and MD5(app key + the random bytes) in bytes 2:17,
  // read and checked here byte by byte (docs/psdk.md#frames), not with the payload's identity code.
  std::array<uint8_t, 16> random{};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::uniform_int_distribution<int> nonzero(1, 255);  // all 16 bytes count (docs/psdk.md#frames)
    for (uint8_t& b : random) b = static_cast<uint8_t>(nonzero(random_));
  }
  IdentityResult result;
  const AckResult raw = session_->request_raw({0x01, 0x01}, random.data(), random.size());
  if (!raw.received) {
    result.detail = raw.message;
  } else {
    result.answered = true;
    const std::string& key = options_.credentials.app_key;
    const Md5Digest expected =
        md5(reinterpret_cast<const uint8_t*>(key.data()), key.size(), random.data(), random.size());
    const bool ok = raw.data.size >= 1 && raw.code() == 0x00;
    result.passed = ok && raw.data.size >= 17 &&
                    std::equal(expected.begin(), expected.end(), raw.data.data() + 1);
    result.detail = result.passed ? "payload proved the app key"
                    : !ok         ? "payload refused: " + ack_code_text(raw.code())
                                  : "MD5 does not match the app key";
  }
  std::lock_guard<std::mutex> lock(mutex_);
  ++(result.passed ? stats_.identity_passed : stats_.identity_failed);
  return result;
}

// --- switches and readings
// -------------------------------------------------------------------------

ByteFaults AdapterSimulator::byte_faults() const {
  return faulty_->faults();
}

ProtocolFaults AdapterSimulator::protocol_faults() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return protocol_faults_;
}

void AdapterSimulator::set_byte_faults(const ByteFaults& faults) {
  faulty_->set_faults(faults);
}

void AdapterSimulator::set_protocol_faults(const ProtocolFaults& faults) {
  std::lock_guard<std::mutex> lock(mutex_);
  protocol_faults_ = faults;
}

void AdapterSimulator::silence_for(std::chrono::milliseconds duration) {
  faulty_->silence_for(duration);
}

void AdapterSimulator::disconnect_for(std::chrono::milliseconds duration) {
  faulty_->disconnect_for(duration);
}

void AdapterSimulator::jump_sequence(uint16_t count) {
  session_->skip_sequence(count);
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.sequence_jumps;
}

void AdapterSimulator::announce_power_off() {
  const double now = elapsed_s();
  std::lock_guard<std::mutex> lock(mutex_);
  power_off_from_s_ = now;
}

AdapterStats AdapterSimulator::stats() const {
  AdapterStats s;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    s = stats_;
  }
  s.session = session_->stats();
  s.byte_faults = faulty_->fault_stats();
  return s;
}

std::vector<std::string> AdapterSimulator::floating_window_messages() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return floating_window_;
}

}  // namespace k40t::psdk::sim
