// The simulated pod on a link: the model (PodModel) behind the protocol (request handlers,
// periodic reports, status frames, the pod's own GPS request before each photo), served through
// a Session in the pod's role on a FaultyTransport, with capture and the control socket.
//
// Threads: the session's I/O thread answers requests; the server's tick thread advances the
// model in real time (steps of SimOptions::tick_s), sends what is due, fires scheduled faults,
// sends delayed ACKs and reopens a disconnected link; the control socket has its own thread.
// One mutex guards the model; frames are built under it and sent after it is released.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "k40t_driver/session/session.h"
#include "k40t_driver/sim/capture_writer.h"
#include "k40t_driver/sim/control_commands.h"
#include "k40t_driver/sim/control_server.h"
#include "k40t_driver/sim/fault_injector.h"
#include "k40t_driver/sim/faulty_transport.h"
#include "k40t_driver/sim/pod_model.h"
#include "k40t_driver/sim/pod_reports.h"
#include "k40t_driver/sim/sim_options.h"

namespace k40t::sim {

class PodServer : public ControlTarget {
 public:
  explicit PodServer(SimOptions options);
  ~PodServer() override;
  PodServer(const PodServer&) = delete;
  PodServer& operator=(const PodServer&) = delete;

  // Opens the link, the capture files and the control socket, and starts the simulation.
  Status start();
  void stop();

  // ControlTarget (the control socket, and tests).
  FaultInjector& faults() override { return faults_; }
  void disconnect_for(std::chrono::milliseconds duration) override;
  void with_model(const std::function<void(PodModel&)>& change) override;
  std::string status() override;

  session::SessionStats session_stats() const;
  const SimOptions& options() const { return options_; }
  int control_port() const { return control_.port(); }

 private:
  // ok once the link is up (or a tcp-server listens), or why its first attempt failed.
  Status first_attempt() const;
  struct DelayedAck {
    SteadyClock::time_point due;
    protocol::FrameHeader request;
    protocol::Payload payload;
  };
  struct Outgoing {
    protocol::Address source;
    OutgoingMessage message;
  };

  std::optional<protocol::Payload> on_request(const protocol::FrameView& request);
  void run();
  void advance_model(double dt_s, std::vector<Outgoing>& out, std::vector<GpsRequestEvent>& gps);
  void send(const std::vector<Outgoing>& out);
  void ask_for_gps(const GpsRequestEvent& request);
  void fire_scheduled_faults(SteadyClock::time_point now);
  void send_due_acks(SteadyClock::time_point now);
  // calibration_end: ack: holds an accepted calibration's ACK; true if it did.
  bool hold_calibration_ack(const protocol::FrameView& request, const protocol::Payload& ack);
  void release_calibration_ack(bool succeeded);  // under model_mutex_

  SimOptions options_;
  FaultInjector faults_;
  std::deque<std::pair<SteadyClock::time_point, GpsRequestEvent>> delayed_gps_;  // run() only
  std::unique_ptr<CaptureWriter> capture_;
  FaultyTransport* link_ = nullptr;  // owned by session_
  std::unique_ptr<session::Session> session_;
  ControlServer control_;

  mutable std::mutex model_mutex_;
  PodModel pod_;
  ReportScheduler scheduler_;

  std::mutex delayed_mutex_;
  std::deque<DelayedAck> delayed_;
  // Under calibration_end: ack the pod answers a calibration when it is done: its OK ACK waits
  // here until then (docs/protocol/decisions.md#conventions).
  std::optional<DelayedAck> calibration_ack_;
  std::vector<ScheduledFault> pending_faults_;
  SteadyClock::time_point started_at_{};

  std::atomic<bool> running_{false};
  std::mutex wake_mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace k40t::sim
