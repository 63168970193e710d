// The payload side of the SKYPORT link, ROS-free: answers the adapter's payload-state commands
// (identity verification with the app key, versions, hand-shake, product information, alias) and
// the camera and gimbal sets by driving the pod through a PodPort; what the pod cannot do is
// answered 0x02 (unsupported) or 0x01 (error), never a made-up success. The battery push's
// power-off announcement stops the pod's recording first, then ACKs "ready".
//
// Commands that drive the pod are answered from a worker thread (the session's handlers must not
// block its I/O thread): the handler queues the job, the job sends the ACK with send_ack() when the
// command asked for one. The queue is bounded: when full, the command is answered 0x01 ("busy") at
// once and counted. Getters never wait for the pod: they answer on the session thread from the
// pod's latest state (PodPort::snapshot()) and what the bridge itself commanded.
#pragma once

#include <chrono>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/psdk/commands/header_variants.h"
#include "k40t_driver/psdk/session.h"
#include "k40t_driver/skyport/ack_reply.h"
#include "k40t_driver/skyport/job_queue.h"
#include "k40t_driver/skyport/photo_progress.h"
#include "k40t_driver/skyport/pod_port.h"

namespace k40t::driver::skyport {

struct BridgeOptions {
  std::string app_key;  // proves identity; never logged
  std::string product_name = "K40T";
  std::string product_id = "k40t_driver";  // skyport_config: the app id by default, as DJI's code
  // 0x01/0x05: the SKYPORT protocol version this payload was written for (PSDK v1.0).
  psdk::Version skyport_version{1, 0, 0, 0};
  std::string developer_account;
  std::string alias = "K40T gimbal pod";
  psdk::Version firmware{1, 0, 0, 0};
  // The telephoto lens (sim/lens.h's K40T-like optics): focal length at 1x, optical and hybrid
  // maxima. PSDK optical zoom is the focal length, digital zoom a factor on top.
  double tele_focal_length_mm = 4.7;
  double max_optical_zoom = 11.0;
  double max_hybrid_zoom = 160.0;
  // How long the pod may take to store a single photo when nothing else tells (photo_progress.h).
  double photo_storing_s = 2.0;
  // Where DJI's published headers and the document disagree (header_variants.h, docs/psdk.md
  // P28..P30): the gimbal state's mode numbering, the SD card state bits, the interval width.
  psdk::PsdkLayout gimbal_mode_layout = psdk::PsdkLayout::kDjiHeaders;
  psdk::PsdkLayout sd_card_layout = psdk::PsdkLayout::kDjiHeaders;
  psdk::PsdkLayout interval_layout = psdk::PsdkLayout::kDjiHeaders;
  // 3.5.1's and 3.5.5's angles: the pod's attitude in NED (DJI's headers; kDjiHeaders, the
  // default: both sources favour it, docs/psdk.md P28), 3.5.5 converted to the joint target with
  // the pod's attitude-minus-joint offset (gimbal_frame.h); or joint angles (kDocument). 3.5.6 is
  // joint angles either way.
  psdk::PsdkLayout gimbal_angle_layout = psdk::PsdkLayout::kDjiHeaders;
  // Pod commands waiting for the worker at most; more are answered "busy" (0x01) at once.
  size_t max_queued_jobs = 8;
  // After the pod accepted a calibration, how long its repair report (0x000008) may stay away
  // before the progress is answered 0x01 (unknown) instead of "in progress".
  double calibration_report_timeout_s = 30.0;
};

struct BridgeStats {
  uint64_t identity_requests = 0;
  uint64_t identity_refused = 0;  // too few random bytes
  uint64_t pod_calls = 0;
  uint64_t pod_call_failures = 0;
  uint64_t unsupported_answers = 0;  // known commands the pod cannot do (0x02)
  uint64_t invalid_commands = 0;     // out of the document's or the pod's range (0x01)
  uint64_t busy_answers = 0;         // the work queue was full (0x01 at once)
  uint64_t queued_jobs = 0;          // waiting for the worker now
  uint64_t battery_pushes = 0;
  bool power_off_announced = false;
  bool power_off_ready = false;
};

class SkyportBridge {
 public:
  using BatteryObserver = std::function<void(const psdk::BatteryInfoPush&)>;
  using Log = std::function<void(const std::string&)>;

  // Registers every handler on `session` (before it starts). `battery` sees every battery push.
  SkyportBridge(psdk::Session& session, PodPort& pod, BridgeOptions options,
                BatteryObserver battery, Log log);
  ~SkyportBridge();
  SkyportBridge(const SkyportBridge&) = delete;
  SkyportBridge& operator=(const SkyportBridge&) = delete;

  BridgeStats stats() const;
  // A message for DJI Pilot's floating window (0x02/0x03), at most 127 bytes (longer is cut).
  void floating_window(const std::string& text);

 private:
  void register_payload_state();
  void register_camera();
  void register_camera_lens();
  void register_gimbal();
  void register_battery();
  void register_widgets();  // skyport_widgets.cpp
  psdk::AckCode set_widget(const psdk::WidgetValue& widget);

  // A command answered from the worker: `answer(const Cmd&)` returns Cmd::Ack or an AckCode.
  template <class Cmd, class F>
  void deferred(F answer);
  // deferred() for a command whose DATA `decode(bytes, size)` reads (a layout variant).
  template <class Cmd, class Decode, class F>
  void deferred_raw(Decode decode, F answer);
  // Get answered from the pod's latest state by `answer(snapshot)`, or refused (kError) while the
  // snapshot's `known` is false: the bridge does not guess.
  template <class Get, class Answer>
  void from_snapshot(bool PodSnapshot::*known, Answer answer);
  // A mode the pod cannot report back: `send(const Set&)` sets it on the pod, the mode the pod
  // accepted is kept in `kept`, and Get is answered from there (skyport_lens.cpp).
  template <class Set, class Get, class Mode, class Send>
  void kept_mode(Mode SkyportBridge::*kept, Send send);
  // The pod's answer as a return code (and counted).
  psdk::AckCode pod_code(const PodCall& call, const char* what);
  psdk::AckCode unsupported();
  psdk::AckCode invalid(const std::string& why);
  // Queues `job` for the worker; false (and counted) when the queue is full.
  bool queue(std::function<void()> job);
  struct ZoomSplit {
    double optical = 1, digital = 1;
  };
  // The zoom as PSDK sees it now (skyport_lens.cpp).
  ZoomSplit zoom_split(const PodSnapshot& s) const;
  // Sets the commanded zoom (optical focal-length factor x digital factor) and drives the pod.
  psdk::AckCode apply_zoom(double optical, double digital);
  psdk::CalibrationProgressAck calibration_progress(const PodSnapshot& s) const;
  // pod_code() for a capture command the pod refuses while it takes a photo (photo_progress_).
  psdk::AckCode capture_code(const PodCall& call, const char* what);

  psdk::Session& session_;
  PodPort& pod_;
  BridgeOptions options_;
  BatteryObserver battery_;
  Log log_;

  mutable std::mutex mutex_;
  BridgeStats stats_;
  double optical_zoom_ = 1.0;  // commanded through PSDK (written by the worker)
  double digital_zoom_ = 1.0;
  bool zoom_follows_pod_ = true;  // no set since start or since a continuous zoom (skyport_lens)
  psdk::MeteringMode metering_ = psdk::MeteringMode::kCenter;
  psdk::FocusMode focus_mode_ = psdk::FocusMode::kAuto;
  float focus_x_ = 0.5f, focus_y_ = 0.5f;
  // The calibration the pod last accepted: when, and how many repair reports had come before it.
  struct Calibration {
    std::chrono::steady_clock::time_point accepted;
    uint64_t repair_reports_before = 0;
  };
  std::optional<Calibration> calibration_;
  bool power_off_job_pending_ = false;  // stopping the pod's recording before "ready" is under way
  int32_t palette_item_ = 0;            // the palette widget's choice
  bool laser_pressed_ = false;  // the laser button is down, ranged for this press (worker only)
  PhotoProgress photo_progress_;

  JobQueue jobs_;  // last: stopped first, while everything its jobs use still exists
};

// --- template ------------------------------------------------------------------------------------

template <class Cmd, class F>
void SkyportBridge::deferred(F answer) {
  deferred_raw<Cmd>(
      [](const uint8_t* bytes, size_t size) { return psdk::decode_data<Cmd>(bytes, size); },
      std::move(answer));
}

template <class Get, class Answer>
void SkyportBridge::from_snapshot(bool PodSnapshot::*known, Answer answer) {
  session_.handle<Get>([this, known, answer](const Get&) -> typename Get::Ack {
    const PodSnapshot s = pod_.snapshot();
    if (!(s.*known)) return detail::refused<typename Get::Ack>(psdk::AckCode::kError);
    return answer(s);
  });
}

template <class Cmd, class Decode, class F>
void SkyportBridge::deferred_raw(Decode decode, F answer) {
  session_.on_command(
      Cmd::key(),
      [this, decode, answer](const psdk::IncomingCommand& in) -> std::optional<psdk::Data> {
        const auto command = decode(in.data.data(), in.data.size);
        if (!command) {
          session_.note_decode_error();
          return detail::reply_data(psdk::AckCode::kError);
        }
        const Status valid = psdk::validate(command.value());
        if (!valid) return detail::reply_data(invalid(valid.message()));
        // The session sends a returned reply only when the command asked for an ACK; the job
        // obeys the same bits.
        const bool wants_ack = in.header.ack_request != psdk::AckRequest::kNoAck;
        const bool queued =
            queue([this, answer, wants_ack, header = in.header, c = command.value()] {
              const auto reply = answer(c);
              if (wants_ack) session_.send_ack(header, detail::reply_data(reply));
            });
        if (!queued) return detail::reply_data(psdk::AckCode::kError);  // busy
        return std::nullopt;
      });
}

}  // namespace k40t::driver::skyport
