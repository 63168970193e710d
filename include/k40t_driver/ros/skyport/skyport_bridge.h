// The payload side of the SKYPORT link, ROS-free: answers the adapter's payload-state commands
// (identity verification with the app key, versions, hand-shake, product information, alias) and
// the camera and gimbal sets by driving the pod through a PodPort; what the pod cannot do is
// answered 0x02 (unsupported) or 0x01 (error), never a made-up success. The battery push's
// power-off announcement stops the pod's recording first, then ACKs "ready".
//
// Commands that need the pod are answered from a worker thread (the session's handlers must not
// block its I/O thread): the handler queues the job, the job sends the ACK with send_ack().
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/psdk/session.h"
#include "k40t_driver/ros/skyport/ack_reply.h"
#include "k40t_driver/ros/skyport/photo_progress.h"
#include "k40t_driver/ros/skyport/pod_port.h"

namespace k40t::driver::skyport {

struct BridgeOptions {
  std::string app_key;  // proves identity; never logged
  std::string product_name = "K40T";
  std::string product_id = "k40t_driver";
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
};

struct BridgeStats {
  uint64_t identity_requests = 0;
  uint64_t identity_refused = 0;  // too few random bytes
  uint64_t pod_calls = 0;
  uint64_t pod_call_failures = 0;
  uint64_t unsupported_answers = 0;  // known commands the pod cannot do (0x02)
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
  // The pod's answer as a return code (and counted).
  psdk::AckCode pod_code(const PodCall& call, const char* what);
  psdk::AckCode unsupported();
  psdk::AckCode apply_zoom();
  // pod_code() for a capture command the pod refuses while it takes a photo (photo_progress_).
  psdk::AckCode capture_code(const PodCall& call, const char* what);
  void run_worker();

  psdk::Session& session_;
  PodPort& pod_;
  BridgeOptions options_;
  BatteryObserver battery_;
  Log log_;

  mutable std::mutex mutex_;
  BridgeStats stats_;
  double optical_zoom_ = 1.0;  // commanded through PSDK (worker thread only)
  double digital_zoom_ = 1.0;
  psdk::MeteringMode metering_ = psdk::MeteringMode::kCenter;
  psdk::FocusMode focus_mode_ = psdk::FocusMode::kAuto;
  float focus_x_ = 0.5f, focus_y_ = 0.5f;
  bool calibrated_ = false;             // the pod acknowledged a calibration
  bool power_off_job_pending_ = false;  // stopping the pod's recording before "ready" is under way
  int32_t palette_item_ = 0;            // the palette widget's choice (worker thread only)
  PhotoProgress photo_progress_;

  std::mutex jobs_mutex_;
  std::condition_variable jobs_wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::thread worker_;
};

// --- template ------------------------------------------------------------------------------------

template <class Cmd, class F>
void SkyportBridge::deferred(F answer) {
  session_.on_command(Cmd::key(),
                      [this, answer](const psdk::IncomingCommand& in) -> std::optional<psdk::Data> {
                        const Result<Cmd> command = psdk::decode_data<Cmd>(in.data);
                        if (!command) return detail::reply_data(psdk::AckCode::kError);
                        {
                          std::lock_guard<std::mutex> lock(jobs_mutex_);
                          jobs_.push_back([this, answer, header = in.header, c = command.value()] {
                            session_.send_ack(header, detail::reply_data(answer(c)));
                          });
                        }
                        jobs_wake_.notify_one();
                        return std::nullopt;
                      });
}

}  // namespace k40t::driver::skyport
