// The driver itself, without ROS: one pod link (a Session over the device URL, or in replay mode
// a bare Dispatcher fed with recorded frames), every decoded message delivered to typed handlers
// together with its honest stamp, and the link's background duties:
//   - stamps: reception time of the frame's last byte minus its wire time
//   (docs/protocol/decisions.md#a10); in replay
//     the recorded stamp;
//   - time sync (0x00030E) every time_sync_period;
//   - the gimbal rate command and its dead-man (RateCommander);
//   - answering the pod's GPS requests (0x000310) and asking for the laser target (0x000320)
//     from the latest VehicleState (the answer, ACK 0x010320, reaches on<TargetGpsAck> handlers
//     like any frame, which is also how replay regenerates it);
//   - "pod online" events: the first frame after a (re)connect or after silence, on which the
//     glue re-reads the pod's settings.
// The ROS glue (RosPod) turns the handlers' output into topics and services into requests.
//
// Threads: typed and frame handlers run on the transport's I/O thread (or the replay caller's);
// they must not block. request() may be called from any other thread. on_pod_online handlers run
// on a thread of their own and may block on requests.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "k40t_driver/driver/box_tracking_guard.h"
#include "k40t_driver/driver/convention_tracker.h"
#include "k40t_driver/driver/driver_options.h"
#include "k40t_driver/driver/link_monitor.h"
#include "k40t_driver/driver/rate_commander.h"
#include "k40t_driver/driver/vehicle_state.h"
#include "k40t_driver/geo/state_history.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/session/dispatcher.h"
#include "k40t_driver/session/session.h"

namespace k40t::driver {

// Nanoseconds since the epoch of the clock the glue provides (ROS time).
using StampNs = int64_t;

struct DriverStats {
  session::SessionStats session;         // link, parser and request counters
  double seconds_since_last_frame = -1;  // -1: no frame yet
  uint64_t pod_online_events = 0;
  uint64_t time_syncs_sent = 0;
  uint64_t gps_requests_answered = 0;
  uint64_t gps_requests_unanswerable = 0;    // no fix yet, or a position the wire cannot carry:
                                             // answered with the failure code
  uint64_t gps_requests_time_matched = 0;    // answered with the state at the requested time
  uint64_t gps_requests_out_of_history = 0;  // the time was outside the history: nearest state
  double last_geotag_gap_s = -1;  // last answer: requested time to the nearest fix (-1: none)
  uint64_t deadman_stops = 0;
  protocol::CrcCoverage crc_coverage = protocol::CrcCoverage::kAuto;  // locked coverage
};

class PodDriver {
 public:
  using Clock = std::function<StampNs()>;
  using FrameHandler = std::function<void(const protocol::FrameView&, StampNs)>;
  using LinkStateHandler = std::function<void(transport::LinkState, const std::string&)>;
  using LinkReportHandler = std::function<void(const PodLinkReport&)>;

  // Builds the link (live: the transport for options.device and its Session, not yet started;
  // replay: a Dispatcher). Fails only for a bad URL. `clock` stamps received frames; pass the
  // ROS clock so that sim time works.
  static Result<std::unique_ptr<PodDriver>> create(DriverOptions options, Clock clock);
  ~PodDriver();  // stop()s
  PodDriver(const PodDriver&) = delete;
  PodDriver& operator=(const PodDriver&) = delete;

  // --- register before start() -------------------------------------------------------------
  // Handlers get the true values: the open readings (docs/protocol/decisions.md#conventions) are
  // applied to 0x000002, 0x000003 and ACK 0x010100 (ConventionTracker::applied).
  template <class Msg>
  void on(std::function<void(const Msg&, StampNs)> handler);
  void on_rx_frame(FrameHandler handler);  // every good frame received
  void on_tx_frame(FrameHandler handler);  // every frame written
  void on_link_state(LinkStateHandler handler);
  // Every change of the link's state as a user reads it (link_monitor.h); runs on the I/O thread,
  // the timer thread or stop()'s caller.
  void on_link_report(LinkReportHandler handler);
  // Asked when the transport reports the loss of an open link (again and again for up to 250 ms,
  // on the I/O thread): true means the process is shutting down (a Ctrl-C reaches the simulator
  // or the other end too, which may close the link first), and the loss is reported as the stop
  // it is.
  void set_shutdown_query(std::function<bool()> shutting_down);
  void on_pod_online(std::function<void()> handler);

  // Opens the link (live) and starts the background threads. An absent device is not an error:
  // the transport retries in the background.
  Status start();
  void stop();

  // Replay mode: one recorded frame (STX .. checksum) with its recorded stamp.
  void replay_frame(const uint8_t* frame, size_t size, StampNs stamp);

  // --- requests (live mode; in replay mode they fail with "replay mode" and send nothing) ---
  template <class Req>
  session::AckResult request(const Req& request);
  template <class Req>
  Result<typename Req::Ack> request_typed(const Req& request, session::AckResult* raw = nullptr);
  session::AckResult request_raw(protocol::MessageId id, const uint8_t* payload, size_t size);
  // Non-blocking; `done` runs on the session's request thread.
  template <class Req>
  void request_async(const Req& request, std::function<void(const session::AckResult&)> done);

  // Gimbal rates in the pod's convention (deg/s, pitch up positive, yaw right positive); the
  // gimbal stops cmd_rate_timeout after the last call.
  void command_rate(double pitch_deg_s, double yaw_deg_s);
  void set_vehicle_state(const VehicleState& state);
  VehicleState vehicle_state() const;
  // The history the GPS answers are interpolated in (stamps: the Clock's, i.e. ROS time).
  void record_position(StampNs stamp, const geo::PositionSample& sample);
  void record_attitude(StampNs stamp, const geo::AttitudeSample& sample);
  void record_velocity(StampNs stamp, const geo::VelocitySample& sample);
  // The vehicle state at `stamp` from the history (position, attitude, velocity interpolated;
  // heights converted as for the latest state), or the latest state when the history holds no
  // position. `in_history` false: the nearest sample stood in.
  VehicleState vehicle_state_at(StampNs stamp, bool* in_history = nullptr,
                                double* gap_s = nullptr) const;
  // The Clock's stamp (ROS time) of a Unix time read on the pod's clock, which the time syncs
  // set to the system clock plus the offset of set_clock_offset_ms().
  StampNs stamp_of_pod_time(int64_t pod_unix_ms) const;
  // The inverse: the pod-clock (UTC) milliseconds of a Clock stamp.
  int64_t pod_time_of_stamp(StampNs stamp) const;
  // Time syncs (0x00030E) use the system clock plus this offset from now on: a better clock's
  // reading minus the system clock at the same instant (e.g. the SKYPORT's UTC/PPS, through the
  // time_reference topic).
  void set_clock_offset_ms(int64_t offset_ms);

  DriverStats stats() const;
  PodLinkReport link_report() const;
  transport::LinkState link_state() const;
  bool replay() const { return options_.replay; }
  const DriverOptions& options() const { return options_; }
  // The codec options in force now: ack_byte_order as the link's setting has it (auto locks it on
  // the pod's first telling ACK, protocol/ack_order_setting.h), the rest as configured.
  protocol::CodecOptions codec() const { return ack_order_->codec_with(options_.session.codec); }
  const protocol::AckOrderSetting& ack_order() const { return *ack_order_; }
  // The open readings in force, where they came from, and what the traffic said against them.
  const ConventionTracker& conventions() const { return conventions_; }
  std::vector<ConventionStatus> conventions_report();

 private:
  PodDriver(DriverOptions options, Clock clock);
  session::Dispatcher& dispatcher();
  session::AckResult not_sent_in_replay() const;
  void handle_rx_frame(const protocol::FrameView& frame);
  void observe_sent(const protocol::FrameView& frame);      // gimbal commands, for the sign checks
  void observe_received(const protocol::FrameView& frame);  // calibration ACKs
  void handle_link_state(transport::LinkState state, const std::string& reason);
  void deliver(const std::optional<PodLinkReport>& report);
  bool shutdown_explains_loss();
  std::optional<protocol::Payload> answer_gps_request(const protocol::FrameView& frame);
  void timer_loop();
  void online_loop();
  void send_time_sync();
  void send_laser_target_request();
  void send_rate_output(const RateCommander::Output& output);
  void track_dial_speed(const protocol::FrameView& frame);
  // docs: driver/box_tracking_guard.h. Blocking: ok when tracking is off (or now switched off).
  Status box_tracking_off_first();
  // Non-blocking: tracking off, then the request (its `done` gets the refusal of either).
  void box_tracking_off_then(protocol::MessageId id, const protocol::Payload& payload,
                             std::function<void(const session::AckResult&)> done);

  using SteadyClock = std::chrono::steady_clock;

  DriverOptions options_;
  Clock clock_;
  ConventionTracker conventions_;
  std::unique_ptr<session::Session> session_;             // live mode
  std::unique_ptr<session::Dispatcher> replayer_;         // replay mode
  const protocol::AckOrderSetting* ack_order_ = nullptr;  // the session's or the replayer's
  double seconds_per_byte_ = 0;

  std::vector<FrameHandler> rx_handlers_;
  std::vector<FrameHandler> tx_handlers_;
  std::vector<LinkStateHandler> link_handlers_;
  std::vector<std::function<void()>> online_handlers_;
  std::vector<LinkReportHandler> link_report_handlers_;
  std::function<bool()> shutting_down_;

  // The stamp of the frame being dispatched (set before typed routing, read by typed handlers
  // on the same thread).
  StampNs current_stamp_ = 0;
  StampNs replay_stamp_ = 0;

  mutable std::mutex mutex_;  // everything below
  std::condition_variable wake_;
  bool stopping_ = false;
  bool started_ = false;
  SteadyClock::time_point last_frame_{};
  bool have_frame_ = false;
  bool reconnected_since_frame_ = true;  // the first frame ever is an online event
  bool online_pending_ = false;
  VehicleState vehicle_;
  geo::StateHistory history_;
  int64_t clock_offset_ms_ = 0;
  RateCommander rate_;
  LinkMonitor link_monitor_;
  BoxTrackingGuard box_tracking_;
  DriverStats counters_;  // the driver's own counters (session stats are read live)

  std::thread timer_thread_;
  std::thread online_thread_;
};

// --- template implementations ------------------------------------------------------------------

template <class Msg>
void PodDriver::on(std::function<void(const Msg&, StampNs)> handler) {
  dispatcher().on<Msg>(
      [this, handler = std::move(handler)](const Msg& message, const protocol::FrameView&) {
        if constexpr (ConventionTracker::kApplies<Msg>) {
          handler(conventions_.applied(message), current_stamp_);
        } else {
          handler(message, current_stamp_);
        }
      });
}

template <class Req>
session::AckResult PodDriver::request(const Req& request) {
  if (!session_) return not_sent_in_replay();
  if (drives_gimbal(request)) {
    Result<protocol::Payload> payload = protocol::encode_payload(request, codec());
    if (!payload) return session::AckResult::not_sent(payload.error());
    const Status off = box_tracking_off_first();
    if (!off) return session::AckResult::not_sent(off.message());
    return session_->request_raw(Req::kId, payload->data(), payload->size);
  }
  return session_->request(request);
}

template <class Req>
Result<typename Req::Ack> PodDriver::request_typed(const Req& request, session::AckResult* raw) {
  if (!session_) {
    if (raw) *raw = not_sent_in_replay();
    return Result<typename Req::Ack>::fail(not_sent_in_replay().message);
  }
  Result<typename Req::Ack> ack = session_->request_typed(request, raw);
  if constexpr (ConventionTracker::kApplies<typename Req::Ack>) {
    if (!ack) return ack;
    if constexpr (std::is_same_v<typename Req::Ack, protocol::ThermalSettingsAck>)
      conventions_.observe_thermal_settings(*ack);
    return conventions_.applied(*ack);
  } else {
    return ack;
  }
}

template <class Req>
void PodDriver::request_async(const Req& request,
                              std::function<void(const session::AckResult&)> done) {
  if (!session_) {
    done(not_sent_in_replay());
    return;
  }
  Result<protocol::Payload> payload = protocol::encode_payload(request, codec());
  if (!payload) {
    session::AckResult failed;
    failed.message = payload.error();
    done(failed);
    return;
  }
  if (drives_gimbal(request) && box_tracking_.tracking()) {
    box_tracking_off_then(Req::kId, payload.value(), std::move(done));
    return;
  }
  session_->request_async(Req::kId, payload.value(), std::move(done));
}

}  // namespace k40t::driver
