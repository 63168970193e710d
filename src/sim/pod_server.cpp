#include "k40t_driver/sim/pod_server.h"

#include <cstdio>
#include <sstream>

#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/convention_readings.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/flight_controller.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/sim/request_handlers.h"

namespace k40t::sim {

namespace {

// Section 3.1 (gimbal, system 0x03): reports 0x000001-0x000002 and requests 0x000010-0x0000FF.
// Section 3.2.1's reports 0x000003-0x00000F are the camera's (system 0x04) despite their ids.
bool is_gimbal_message(protocol::MessageId id) {
  const protocol::MessageId base = id & 0xFFFF;
  return base == 0x000001 || base == 0x000002 || (base >= 0x000010 && base <= 0x0000FF);
}

void print_frame(const char* direction, const protocol::FrameView& frame) {
  const protocol::MessageInfo* info = protocol::find_message(frame.header.message_id);
  std::printf("%s seq %3u %02X/%02X->%02X/%02X 0x%06X %-28s %zu B\n", direction,
              frame.header.sequence, frame.header.source.system, frame.header.source.component,
              frame.header.destination.system, frame.header.destination.component,
              frame.header.message_id, info ? info->name : "?", frame.payload_size);
  std::fflush(stdout);
}

}  // namespace

namespace {
// The model's part of the readings the pod follows (the rest is in how it encodes).
PodConfig played_config(const SimOptions& o) {
  PodConfig config = o.pod;
  config.camera.self_timer = o.codec.conventions.photo_mode_2 == protocol::PhotoMode2::kSelfTimer;
  return config;
}
}  // namespace

PodServer::PodServer(SimOptions options)
    : options_(std::move(options)),
      faults_(options_.seed, options_.crc_coverage),
      pod_(played_config(options_)) {
  faults_.set_settings(options_.faults);
  if (options_.sd_condition) set_sd_condition(pod_.camera().sd(), *options_.sd_condition);
}

PodServer::~PodServer() {
  stop();
}

Status PodServer::start() {
  if (running_) return Status::ok();
  if (options_.capture_prefix) {
    auto capture = CaptureWriter::open(*options_.capture_prefix);
    if (!capture) return capture.status();
    capture_ = std::move(capture).value();
  }
  // Fail now on a URL no retry can fix; the real link is made again after each disconnect.
  {
    auto probe = transport::make_transport(options_.link);
    if (!probe) return probe.status();
  }
  const std::string url = options_.link;
  auto link = std::make_unique<FaultyTransport>([url] { return transport::make_transport(url); },
                                                url, faults_, capture_.get());
  link_ = link.get();

  session::SessionOptions session_options;
  session_options.codec = options_.codec;
  session_options.crc_coverage = options_.crc_coverage;
  session_options.own_address = options_.codec.camera_address;
  session_ = std::make_unique<session::Session>(std::move(link), session_options);
  for (const HandlerEntry& entry : request_handlers()) {
    session_->set_request_handler(entry.id,
                                  [this](const protocol::FrameView& f) { return on_request(f); });
  }
  if (options_.verbose) {
    session_->dispatcher().on_frame([](const protocol::FrameView& f) { print_frame("rx", f); });
    session_->on_frame_sent([](const protocol::FrameView& f) { print_frame("tx", f); });
  }
  const Status opened = session_->start();
  if (!opened) return opened;
  // The link is made in the background and retried for ever; one the simulator cannot open at all
  // (a pty in a missing directory, a port in use, an address not on this machine) is a start-up
  // failure, which docs/simulator.md promises as exit 1 with the reason.
  if (const Status link = first_attempt(); !link) {
    session_->stop();
    return link;
  }

  if (options_.control_endpoint) {
    const Status control = control_.start(
        *options_.control_endpoint,
        [this](const std::string& line) { return execute_control_command(line, *this); });
    if (!control) {
      session_->stop();
      return control;
    }
  }
  pending_faults_ = options_.scheduled;
  started_at_ = SteadyClock::now();
  running_ = true;
  thread_ = std::thread([this] { run(); });
  return Status::ok();
}

Status PodServer::first_attempt() const {
  // A tcp-server waits for its client while kConnecting: after this long that is a success.
  constexpr auto kPatience = std::chrono::seconds(2);
  const auto deadline = SteadyClock::now() + kPatience;
  while (SteadyClock::now() < deadline) {
    const transport::LinkState state = session_->link_state();
    if (state == transport::LinkState::kConnected) return Status::ok();
    if (state == transport::LinkState::kReconnecting) {
      const std::string why = session_->stats().link.last_error;
      return Status::fail("cannot open " + options_.link + ": " + why);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return Status::ok();
}

void PodServer::stop() {
  if (running_.exchange(false)) {
    {
      std::lock_guard<std::mutex> lock(wake_mutex_);
      wake_.notify_all();
    }
    thread_.join();
  }
  control_.stop();
  if (session_) session_->stop();
}

std::optional<protocol::Payload> PodServer::on_request(const protocol::FrameView& request) {
  std::optional<protocol::Payload> ack;
  if (const std::optional<uint16_t> code = faults_.refusal(request.header.message_id)) {
    protocol::PlainAck refusal;  // refused: the model never sees the request
    refusal.code = static_cast<protocol::ResponseCode>(*code);
    Result<protocol::Payload> encoded = protocol::encode_payload(refusal, options_.codec);
    if (encoded) ack = encoded.value();
  } else {
    std::lock_guard<std::mutex> lock(model_mutex_);
    ack = answer_request(pod_, options_.codec, request);
  }
  if (!ack) return std::nullopt;
  if (hold_calibration_ack(request, *ack)) return std::nullopt;
  // The pod did what was asked; only its answer is lost or late.
  if (faults_.drop_ack()) return std::nullopt;
  const std::chrono::milliseconds delay = faults_.ack_delay();
  if (delay.count() > 0) {
    std::lock_guard<std::mutex> lock(delayed_mutex_);
    delayed_.push_back({SteadyClock::now() + delay, request.header, *ack});
    return std::nullopt;
  }
  return ack;
}

bool PodServer::hold_calibration_ack(const protocol::FrameView& request,
                                     const protocol::Payload& ack) {
  const protocol::MessageId id = request.header.message_id;
  const bool calibration = id == protocol::GimbalDriftCalibrationRequest::kId ||
                           id == protocol::GimbalLinearCalibrationRequest::kId ||
                           id == protocol::GimbalAccelerationCalibrationRequest::kId;
  if (!calibration ||
      options_.codec.conventions.calibration_end != protocol::CalibrationEnd::kAck ||
      protocol::ack_response_code(ack.data(), ack.size, options_.codec) !=
          protocol::ResponseCode::kOk)
    return false;
  std::lock_guard<std::mutex> lock(delayed_mutex_);
  calibration_ack_ = DelayedAck{SteadyClock::now(), request.header, ack};
  return true;
}

void PodServer::release_calibration_ack(bool succeeded) {
  std::lock_guard<std::mutex> lock(delayed_mutex_);
  if (!calibration_ack_) return;
  DelayedAck ack = *calibration_ack_;
  calibration_ack_.reset();
  if (!succeeded) {
    protocol::PlainAck failed;
    failed.code = protocol::ResponseCode::kFailure;
    Result<protocol::Payload> encoded = protocol::encode_payload(failed, options_.codec);
    if (encoded) ack.payload = encoded.value();
  }
  ack.due = SteadyClock::now();
  delayed_.push_front(ack);
}

void PodServer::advance_model(double dt_s, std::vector<Outgoing>& out,
                              std::vector<GpsRequestEvent>& gps) {
  std::lock_guard<std::mutex> lock(model_mutex_);
  pod_.step(dt_s);
  for (const PodEvent& event : pod_.take_events()) {
    const auto* maintenance = std::get_if<MaintenanceEvent>(&event);
    if (maintenance && maintenance->calibration &&
        maintenance->state != MaintenanceState::kRepairing)
      release_calibration_ack(maintenance->state == MaintenanceState::kSucceeded);
    if (const auto* request = std::get_if<GpsRequestEvent>(&event)) {
      pod_.ground_truth().photo_taken(request->photo_id, pod_.pod_position());
      gps.push_back(*request);
    } else if (auto message = encode_event(event, options_.codec)) {
      out.push_back({options_.codec.camera_address, *message});
    }
  }
  for (const PeriodicReport* report : scheduler_.due(pod_, pod_.now_s())) {
    Result<protocol::Payload> payload = report->encode(pod_, options_.codec);
    if (!payload) continue;  // a model value the field cannot carry: skip this one report
    const protocol::Address source = is_gimbal_message(report->id) ? options_.codec.gimbal_address
                                                                   : options_.codec.camera_address;
    out.push_back({source, OutgoingMessage{report->id, *payload}});
  }
}

void PodServer::send(const std::vector<Outgoing>& out) {
  for (const Outgoing& o : out) {
    session_->send_frame_from(o.source, o.message.id, o.message.payload.data(),
                              o.message.payload.size, protocol::kHostAddress);
  }
}

void PodServer::ask_for_gps(const GpsRequestEvent& event) {
  protocol::CameraGpsRequest request;
  // The photo's UTC time of day, in the pod's zone if it reads so (gps_request_time,
  // docs/protocol/decisions.md#conventions).
  const int64_t utc_ms_of_day =
      ((event.time.hour * 60 + event.time.minute) * 60 + event.time.second) * int64_t{1000} +
      event.time.millisecond;
  int32_t minutes_west = 0;
  {
    std::lock_guard<std::mutex> lock(model_mutex_);
    minutes_west = pod_.camera().clock().minutes_west();
  }
  protocol::gps_request_time_to_wire(request, utc_ms_of_day,
                                     options_.codec.conventions.gps_request_time, minutes_west);
  Result<protocol::Payload> payload = protocol::encode_payload(request, options_.codec);
  if (!payload) return;
  const uint64_t photo_id = event.photo_id;
  session_->request_async(
      protocol::CameraGpsRequest::kId, *payload, protocol::kFlightControllerAddress,
      [this, photo_id](const session::AckResult& result) {
        if (!result.ok()) return;  // no GPS: the photo keeps no position
        auto ack = protocol::decode_gps_answer(result.payload.data(), result.payload.size(),
                                               options_.codec);
        if (!ack) return;
        GpsAnswer answer;
        answer.echoed = {ack->hour, ack->minute, ack->second, ack->millisecond};
        answer.position = {ack->latitude_deg, ack->longitude_deg, ack->relative_height_m,
                           ack->altitude_m};
        answer.attitude_deg = {ack->yaw_deg, ack->pitch_deg, ack->roll_deg};
        std::lock_guard<std::mutex> lock(model_mutex_);
        pod_.camera().attach_gps(photo_id, answer);
        pod_.ground_truth().photo_answered(photo_id, pod_.pod_position(), ack->latitude_deg,
                                           ack->longitude_deg, ack->altitude_m);
      });
}

void PodServer::fire_scheduled_faults(SteadyClock::time_point now) {
  for (auto it = pending_faults_.begin(); it != pending_faults_.end();) {
    if (now < started_at_ + it->at) {
      ++it;
      continue;
    }
    const auto duration = std::chrono::milliseconds(static_cast<int64_t>(it->amount * 1000));
    switch (it->kind) {
      case ScheduledFault::Kind::kSilence:
        faults_.silence_for(duration, now);
        break;
      case ScheduledFault::Kind::kDisconnect:
        disconnect_for(duration);
        break;
      case ScheduledFault::Kind::kSequenceJump:
        faults_.jump_sequence(static_cast<int>(it->amount));
        break;
    }
    it = pending_faults_.erase(it);
  }
}

void PodServer::send_due_acks(SteadyClock::time_point now) {
  std::vector<DelayedAck> due;
  {
    std::lock_guard<std::mutex> lock(delayed_mutex_);
    while (!delayed_.empty() && delayed_.front().due <= now) {
      due.push_back(delayed_.front());
      delayed_.pop_front();
    }
  }
  for (const DelayedAck& ack : due)
    session_->send_ack(ack.request, ack.payload.data(), ack.payload.size);
}

void PodServer::run() {
  const auto tick = std::chrono::duration_cast<SteadyClock::duration>(
      std::chrono::duration<double>(options_.tick_s));
  SteadyClock::time_point simulated_until = SteadyClock::now();
  {
    // Model time follows the wall clock from here: the truth's Unix times (control command
    // "truth") count from this instant.
    std::lock_guard<std::mutex> lock(model_mutex_);
    pod_.set_unix_epoch_s(
        std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count() -
        pod_.now_s());
  }
  while (running_) {
    const SteadyClock::time_point now = SteadyClock::now();
    std::vector<Outgoing> out;
    std::vector<GpsRequestEvent> gps;
    // Model time follows the wall clock in fixed steps, so rates hold whatever the scheduling.
    while (simulated_until + tick <= now) {
      advance_model(options_.tick_s, out, gps);
      simulated_until += tick;
    }
    send(out);
    // GPS requests leave gps_request_delay_s after their photo.
    for (const GpsRequestEvent& request : gps)
      delayed_gps_.push_back(
          {now + std::chrono::duration_cast<SteadyClock::duration>(
                     std::chrono::duration<double>(options_.gps_request_delay_s)),
           request});
    while (!delayed_gps_.empty() && delayed_gps_.front().first <= now) {
      ask_for_gps(delayed_gps_.front().second);
      delayed_gps_.pop_front();
    }
    fire_scheduled_faults(now);
    send_due_acks(now);
    link_->poll(now);
    std::unique_lock<std::mutex> lock(wake_mutex_);
    wake_.wait_until(lock, simulated_until + tick, [this] { return !running_; });
  }
}

void PodServer::disconnect_for(std::chrono::milliseconds duration) {
  if (link_) link_->disconnect_for(duration);
}

void PodServer::with_model(const std::function<void(PodModel&)>& change) {
  std::lock_guard<std::mutex> lock(model_mutex_);
  change(pod_);
}

session::SessionStats PodServer::session_stats() const {
  return session_ ? session_->stats() : session::SessionStats{};
}

std::string PodServer::status() {
  const session::SessionStats s = session_stats();
  std::ostringstream out;
  out << "link " << options_.link << " " << transport::to_string(s.link_state) << " | sent "
      << s.frames_sent << " frames, answered " << s.requests_answered << " requests, received "
      << s.parser.frames_good << " good frames, " << s.parser.checksum_errors << " checksum errors";
  with_model([&](PodModel& pod) {
    const GimbalPose pose = pod.gimbal().pose();
    out << " | t " << pod.now_s() << " s yaw " << pose.joint_deg.yaw << " pitch "
        << pose.joint_deg.pitch << " zoom " << pod.zoom().zoom() << "x sd "
        << to_string(pod.camera().sd().state()) << " camera "
        << (pod.camera_available() ? "up" : "down") << " recording "
        << (pod.camera().recording() ? "yes" : "no") << " palette "
        << static_cast<int>(pod.thermal().settings().reported.palette) << " image-mode "
        << static_cast<int>(pod.camera().settings().image_mode) << " focus ";
    if (const auto& area = pod.zoom().focus_area()) {
      out << "area " << area->left << "," << area->top << "-" << area->right << "," << area->bottom;
    } else {
      out << "centre";
    }
    // What the pod is busy with: tests wait on these instead of on a 1 Hz status topic.
    out << " focus-m " << pod.zoom().focus_distance_m() << " roll " << pose.joint_deg.roll;
    out << " shooting " << (pod.camera().shooting() ? "yes" : "no") << " zooming "
        << (pod.zoom().zooming() ? "yes" : "no") << " upgrading "
        << (pod.camera().upgrading() ? "yes" : "no");
  });
  out << " | faults " << faults_.describe();
  return out.str();
}

}  // namespace k40t::sim
