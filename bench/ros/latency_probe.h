// Benchmark probe: plays the pod on a pseudo-terminal and measures how long a byte written there
// takes to come out of the driver as a ROS message.
//
// It creates the pty (the transport's own pty:// scheme, so the driver opens it as serial://),
// writes gimbal attitude reports (0x000002) at `rate` Hz whose joint yaw encodes a counter, and
// subscribes to the driver's joint_states (tcp_nodelay; in the same nodelet manager the message
// comes by pointer). Latency = arrival in the callback - return of the write that carried the
// frame's last byte, both on the steady clock of this process. After `samples` messages it
// prints p50/p99/max and, if `output` is set, appends the line to that file.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <ros/node_handle.h>
#include <ros/subscriber.h>
#include <sensor_msgs/JointState.h>

#include "k40t_driver/transport/transport.h"

namespace k40t::bench {

class LatencyProbe {
 public:
  // Params (private): link (pty path), label, rate (Hz), samples, output (file, optional).
  LatencyProbe(ros::NodeHandle nh, ros::NodeHandle private_nh);
  ~LatencyProbe();

  bool done() const { return done_; }

 private:
  void write_loop();
  void on_joint_states(const sensor_msgs::JointState::ConstPtr& msg);
  void report();

  using Clock = std::chrono::steady_clock;
  static constexpr int kCounterModulo = 20000;  // joint yaw 0..199.99 deg

  std::string label_;
  double rate_hz_ = 50;
  size_t samples_ = 1000;
  std::string output_;
  std::unique_ptr<transport::Transport> pty_;
  ros::Subscriber subscriber_;

  std::mutex mutex_;
  std::vector<Clock::time_point> sent_;  // by counter % kCounterModulo
  std::vector<double> latencies_ms_;
  std::atomic<bool> done_{false};
  std::atomic<bool> stopping_{false};
  std::thread writer_;
};

}  // namespace k40t::bench
