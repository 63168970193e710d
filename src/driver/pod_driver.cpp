#include "k40t_driver/driver/pod_driver.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>

#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver {

using protocol::FrameView;
using session::AckResult;

namespace {

std::chrono::steady_clock::duration seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(s));
}

int64_t unix_time_ms_now() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

Result<std::unique_ptr<PodDriver>> PodDriver::create(DriverOptions options, Clock clock) {
  std::unique_ptr<PodDriver> driver(new PodDriver(std::move(options), std::move(clock)));
  const DriverOptions& o = driver->options_;
  if (o.replay) {
    driver->replayer_ =
        std::make_unique<session::Dispatcher>(o.session.crc_coverage, o.session.codec);
  } else {
    const std::string url = device_url_with_baud(o.device, o.baud);
    Result<std::unique_ptr<transport::Transport>> link = transport::make_transport(url);
    if (!link) return Result<std::unique_ptr<PodDriver>>::fail(link.error());
    driver->seconds_per_byte_ = link.value()->seconds_per_byte();
    transport::ReconnectPolicy policy;
    policy.initial_delay = std::chrono::milliseconds(50);
    policy.max_delay =
        std::chrono::milliseconds(static_cast<int64_t>(o.reconnect_max_delay_s * 1000));
    link.value()->set_reconnect_policy(policy);
    driver->session_ = std::make_unique<session::Session>(std::move(link.value()), o.session);
  }
  driver->ack_order_ = &driver->dispatcher().ack_order();
  // The first frame handler: it stamps the frame for everything that follows (typed handlers
  // run after all frame handlers).
  PodDriver* self = driver.get();
  driver->dispatcher().on_frame([self](const FrameView& frame) { self->handle_rx_frame(frame); });
  // Before any glue handler: the report as decoded locks or checks the readings the handlers'
  // copies are then read with (docs/protocol/decisions.md#conventions).
  driver->dispatcher().on<protocol::GimbalAttitude>(
      [self](const protocol::GimbalAttitude& m, const FrameView&) {
        self->conventions_.observe_attitude(m, ConventionTracker::steady_now_s());
      });
  driver->dispatcher().on<protocol::CameraUpgradeStatus>(
      [self](const protocol::CameraUpgradeStatus& m, const FrameView&) {
        self->conventions_.observe_upgrade_status(m, ConventionTracker::steady_now_s());
      });
  return driver;
}

PodDriver::PodDriver(DriverOptions options, Clock clock)
    : options_(std::move(options)),
      clock_(std::move(clock)),
      conventions_(options_.session.crc_coverage, options_.session.codec,
                   options_.conventions_from_parameters),
      history_(geo::HistoryLimits{options_.state_history_s, 5000}),
      link_monitor_(options_.replay ? std::string("replay")
                                    : device_url_with_baud(options_.device, options_.baud),
                    options_.link_timeout_s) {
  rate_.set_timeout(std::chrono::duration<double>(options_.cmd_rate_timeout_s));
}

PodDriver::~PodDriver() {
  stop();
}

session::Dispatcher& PodDriver::dispatcher() {
  return replayer_ ? *replayer_ : session_->dispatcher();
}

void PodDriver::on_rx_frame(FrameHandler handler) {
  rx_handlers_.push_back(std::move(handler));
}
void PodDriver::on_tx_frame(FrameHandler handler) {
  tx_handlers_.push_back(std::move(handler));
}
void PodDriver::on_link_state(LinkStateHandler handler) {
  link_handlers_.push_back(std::move(handler));
}
void PodDriver::on_pod_online(std::function<void()> handler) {
  online_handlers_.push_back(std::move(handler));
}

Status PodDriver::start() {
  if (started_) return Status::fail("the driver is already started");
  if (session_) {
    session_->on_frame_sent([this](const FrameView& frame) {
      observe_sent(frame);
      track_dial_speed(frame);
      box_tracking_.frame_sent(frame, codec());
      const StampNs stamp = clock_();
      for (const FrameHandler& handler : tx_handlers_) handler(frame, stamp);
    });
    session_->on_link_state([this](transport::LinkState state, const std::string& reason) {
      handle_link_state(state, reason);
    });
    if (options_.answer_gps_requests) {
      session_->set_request_handler(
          protocol::CameraGpsRequest::kId,
          [this](const FrameView& frame) { return answer_gps_request(frame); });
    }
    const Status opened = session_->start();
    if (!opened) return opened;
    timer_thread_ = std::thread([this] { timer_loop(); });
    online_thread_ = std::thread([this] { online_loop(); });
  }
  started_ = true;
  return Status::ok();
}

void PodDriver::stop() {
  std::optional<PodLinkReport> report;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    if (started_ && session_) report = link_monitor_.on_stop();
  }
  wake_.notify_all();
  deliver(report);
  // The session first: a request the online thread is waiting on (the settings read-back) then
  // completes at once with "session stopped" instead of after its timeouts and retries, and the
  // requests still to come fail without waiting, so the joins below take no time.
  if (session_) session_->stop();
  if (timer_thread_.joinable()) timer_thread_.join();
  if (online_thread_.joinable()) online_thread_.join();
}

void PodDriver::replay_frame(const uint8_t* frame, size_t size, StampNs stamp) {
  if (!replayer_) return;
  replay_stamp_ = stamp;
  replayer_->feed_frame(frame, size);
}

AckResult PodDriver::not_sent_in_replay() const {
  AckResult result;
  result.message = "replay mode: there is no pod to send to";
  return result;
}

AckResult PodDriver::request_raw(protocol::MessageId id, const uint8_t* payload, size_t size) {
  if (!session_) return not_sent_in_replay();
  return session_->request_raw(id, payload, size);
}

void PodDriver::handle_rx_frame(const FrameView& frame) {
  // docs/protocol/decisions.md#a10: the pod sends no timestamps; the frame began arriving one wire
  // time before now.
  const StampNs stamp =
      replayer_
          ? replay_stamp_
          : clock_() - static_cast<StampNs>(std::llround(frame.size * seconds_per_byte_ * 1e9));
  current_stamp_ = stamp;
  box_tracking_.frame_received(frame, codec());
  if (!replayer_) {
    const SteadyClock::time_point now = SteadyClock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    const std::optional<PodLinkReport> report = link_monitor_.on_frame(now);
    const bool online = !have_frame_ || reconnected_since_frame_ ||
                        now - last_frame_ > seconds(options_.silence_timeout_s);
    last_frame_ = now;
    have_frame_ = true;
    reconnected_since_frame_ = false;
    if (online) {
      online_pending_ = true;
      rate_.forget_speed();  // back after silence: it may have restarted
      ++counters_.pod_online_events;
    }
    lock.unlock();
    deliver(report);  // "connected" before what the online handlers then say
    if (online) wake_.notify_all();
  }
  observe_received(frame);
  for (const FrameHandler& handler : rx_handlers_) handler(frame, stamp);
}

namespace {
// The heights of the GPS answer as the wire can carry them (int16 x0.1 m).
void clamp_heights(protocol::CameraGpsAck& ack) {
  constexpr double kLimitM = 3276.7;
  ack.relative_height_m = std::clamp(ack.relative_height_m, -kLimitM, kLimitM);
  ack.altitude_m = std::clamp(ack.altitude_m, -kLimitM, kLimitM);
}
}  // namespace

// Every GPS request gets an ACK: the position when there is one the wire can carry, otherwise the
// failure code (the pod tags no position). Counted only once the answer is encoded.
std::optional<protocol::Payload> PodDriver::answer_gps_request(const FrameView& frame) {
  Result<protocol::CameraGpsRequest> request =
      protocol::decode_payload<protocol::CameraGpsRequest>(frame, codec());
  if (!request) return std::nullopt;  // counted as a decode error by the dispatcher too
  const protocol::CameraGpsRequest& asked = request.value();
  bool in_history = true;
  double gap_s = -1;  // stays -1 when the history holds no position (the latest state answers)
  VehicleState vehicle;
  if (options_.geotag_time_match) {
    // The time of day on the pod clock, on the day nearest to the pod's now.
    // In UTC, or in the zone the time syncs give the pod (gps_request_time).
    const int64_t time_of_day_ms = protocol::gps_request_utc_ms_of_day(
        asked, codec().conventions.gps_request_time, options_.time_zone_minutes_west);
    const int64_t pod_now_ms = pod_time_of_stamp(clock_());
    const StampNs at = stamp_of_pod_time(geo::unix_ms_of_time_of_day(time_of_day_ms, pod_now_ms));
    vehicle = vehicle_state_at(at, &in_history, &gap_s);
  } else {
    vehicle = vehicle_state();
  }
  protocol::CameraGpsAck ack = protocol::CameraGpsAck::answering(asked);
  bool positioned = false;
  if (vehicle.has_fix) {
    fill_position(ack, vehicle);
    if (options_.gps_clamp_height) clamp_heights(ack);
    positioned = ack.validate().is_ok();
  }
  if (!positioned) {
    ack = protocol::CameraGpsAck::answering(request.value());  // no position: "no fix yet"
    ack.code = protocol::ResponseCode::kFailure;
  }
  // The data in gps_answer_byte_order, the response code in ack_byte_order.
  Result<protocol::Payload> payload = protocol::encode_gps_answer(ack, codec());
  if (!payload) return std::nullopt;  // the failure form always encodes; kept for safety
  std::lock_guard<std::mutex> lock(mutex_);
  ++(positioned ? counters_.gps_requests_answered : counters_.gps_requests_unanswerable);
  if (positioned && gap_s >= 0) {
    ++counters_.gps_requests_time_matched;
    if (!in_history) ++counters_.gps_requests_out_of_history;
    counters_.last_geotag_gap_s = gap_s;
  }
  return payload.value();
}

void PodDriver::set_clock_offset_ms(int64_t offset_ms) {
  bool changed = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    changed = std::llabs(offset_ms - clock_offset_ms_) > 1000;
    clock_offset_ms_ = offset_ms;
  }
  // A new reference (the first one, or a jump): set the pod's clock now, not a period later.
  if (changed && options_.time_sync_period_s > 0 && session_ &&
      link_state() == transport::LinkState::kConnected)
    send_time_sync();
}

void PodDriver::send_time_sync() {
  protocol::TimeSyncRequest sync;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    sync.unix_time_ms = unix_time_ms_now() + clock_offset_ms_;
  }
  sync.tz_minutes_west = options_.time_zone_minutes_west;  // the pod names its files in local time
  request_async(sync, [](const AckResult&) {});
  std::lock_guard<std::mutex> lock(mutex_);
  ++counters_.time_syncs_sent;
}

void PodDriver::send_laser_target_request() {
  // The latest fix and attitude, with the velocity from the input or the last two fixes.
  const VehicleState vehicle = vehicle_state_at(clock_());
  if (!vehicle.has_fix) return;
  protocol::TargetGpsRequest request;
  request.fix = static_cast<protocol::GpsFixStatus>(vehicle.gps_status);
  // The fix's time in UTC: its stamp through the clock offset (time_reference).
  request.utc_time_ms = static_cast<uint64_t>(pod_time_of_stamp(vehicle.utc_ms * 1000000));
  fill_position(request, vehicle);
  if (vehicle.has_attitude)
    request.heading_deg = std::fmod(std::fmod(vehicle.heading_deg, 360.0) + 360.0, 360.0);
  request.ground_speed_m_s = vehicle.ground_speed_m_s;
  request.climb_rate_m_s = vehicle.climb_rate_m_s;
  request_async(request, [](const AckResult&) {});  // the ACK is dispatched like any frame
}

void PodDriver::timer_loop() {
  transport::name_this_thread("k40t_timer");
  const bool syncing = options_.time_sync_period_s > 0;
  const bool targeting = options_.laser_target_period_s > 0;
  SteadyClock::time_point next_sync = SteadyClock::now() + seconds(options_.time_sync_period_s);
  SteadyClock::time_point next_target =
      SteadyClock::now() + seconds(options_.laser_target_period_s);
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    const SteadyClock::time_point now = SteadyClock::now();
    const RateCommander::Output deadman = rate_.tick(now);
    if (deadman.deadman_stop) ++counters_.deadman_stops;
    const std::optional<PodLinkReport> link_report = link_monitor_.on_tick(now);
    const bool sync_due = syncing && now >= next_sync;
    const bool target_due = targeting && now >= next_target;
    if (sync_due) next_sync = now + seconds(options_.time_sync_period_s);
    if (target_due) next_target = now + seconds(options_.laser_target_period_s);

    lock.unlock();  // sending takes the session's locks, never ours
    if (!deadman.empty()) send_rate_output(deadman);
    if (sync_due) send_time_sync();
    if (target_due) send_laser_target_request();
    deliver(link_report);
    lock.lock();

    SteadyClock::time_point wake = now + std::chrono::seconds(1);
    if (syncing) wake = std::min(wake, next_sync);
    if (targeting) wake = std::min(wake, next_target);
    if (const auto deadline = rate_.deadline()) wake = std::min(wake, *deadline);
    if (const auto deadline = link_monitor_.deadline()) wake = std::min(wake, *deadline);
    wake_.wait_until(lock, wake, [&] {
      const auto link_due = link_monitor_.deadline();
      return stopping_ || (rate_.deadline() && *rate_.deadline() < wake) ||
             (link_due && *link_due < wake);
    });
  }
}

void PodDriver::online_loop() {
  transport::name_this_thread("k40t_online");
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    wake_.wait(lock, [&] { return stopping_ || online_pending_; });
    if (stopping_) break;
    online_pending_ = false;
    lock.unlock();
    // The pod is (back) online: sync its clock now rather than up to a period later, then let the
    // glue re-read its settings (blocking requests, hence this thread).
    if (options_.time_sync_period_s > 0) send_time_sync();
    for (const auto& handler : online_handlers_) handler();
    lock.lock();
  }
}

DriverStats PodDriver::stats() const {
  DriverStats out;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    out = counters_;
    out.seconds_since_last_frame =
        have_frame_ ? std::chrono::duration<double>(SteadyClock::now() - last_frame_).count()
                    : -1.0;
  }
  if (session_) {
    out.session = session_->stats();
    out.crc_coverage = session_->dispatcher().stats().locked_coverage;
  } else if (replayer_) {
    const session::DispatcherStats replay = replayer_->stats();
    out.session.parser = replay.parser;
    out.session.decode_errors = replay.decode_errors;
    out.crc_coverage = replay.locked_coverage;
  }
  return out;
}

transport::LinkState PodDriver::link_state() const {
  return session_ ? session_->link_state() : transport::LinkState::kClosed;
}

}  // namespace k40t::driver
