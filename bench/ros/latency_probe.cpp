#include "latency_probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <ros/console.h>
#include <ros/this_node.h>

#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::bench {

LatencyProbe::LatencyProbe(ros::NodeHandle nh, ros::NodeHandle private_nh) : sent_(kCounterModulo) {
  const std::string link = private_nh.param<std::string>("link", "/tmp/k40t_bench_pty");
  label_ = private_nh.param<std::string>("label", "joint_states");
  rate_hz_ = private_nh.param("rate", 50.0);
  samples_ = static_cast<size_t>(private_nh.param("samples", 1000));
  output_ = private_nh.param<std::string>("output", "");

  Result<std::unique_ptr<transport::Transport>> pty = transport::make_transport("pty://" + link);
  if (!pty) {
    ROS_FATAL("latency probe: %s", pty.error().c_str());
    done_ = true;
    return;
  }
  pty_ = std::move(pty.value());
  pty_->set_receive_callback([](const uint8_t*, size_t) {});  // the driver's requests go unanswered
  const Status opened = pty_->open();
  if (!opened) {
    ROS_FATAL("latency probe: %s", opened.message().c_str());
    done_ = true;
    return;
  }
  subscriber_ = nh.subscribe("joint_states", 100, &LatencyProbe::on_joint_states, this,
                             ros::TransportHints().tcpNoDelay());
  writer_ = std::thread([this] { write_loop(); });
}

LatencyProbe::~LatencyProbe() {
  stopping_ = true;
  if (writer_.joinable()) writer_.join();
  if (pty_) pty_->close();
}

void LatencyProbe::write_loop() {
  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz_));
  Clock::time_point next = Clock::now();
  uint8_t sequence = 0;
  for (int counter = 0; !stopping_ && !done_; counter = (counter + 1) % kCounterModulo) {
    protocol::GimbalAttitude attitude;
    attitude.joint_yaw_deg = counter / 100.0;
    Result<protocol::Payload> payload = protocol::encode_payload(attitude);
    protocol::FrameHeader header;
    header.destination = protocol::kHostAddress;
    header.source = protocol::kGimbalAddress;
    header.sequence = sequence++;
    header.message_id = protocol::GimbalAttitude::kId;
    Result<protocol::EncodedFrame> frame = protocol::encode_frame(
        header, payload->data(), payload->size, protocol::CrcCoverage::kHeaderExcluded);
    const Status sent = pty_->send(frame->data(), frame->size());
    {
      std::lock_guard<std::mutex> lock(mutex_);
      sent_[counter] = Clock::now();  // the write has returned: the bytes are readable
    }
    if (!sent) std::this_thread::sleep_for(std::chrono::milliseconds(50));  // driver not there yet
    next += period;
    std::this_thread::sleep_until(next);
  }
}

void LatencyProbe::on_joint_states(const sensor_msgs::JointState::ConstPtr& msg) {
  const Clock::time_point arrival = Clock::now();
  if (msg->position.empty() || done_) return;
  // joint_states yaw = -pod yaw (REP 103).
  const int counter = static_cast<int>(std::lround(-msg->position[0] * 180.0 / M_PI * 100.0));
  if (counter < 0 || counter >= kCounterModulo) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const Clock::time_point sent = sent_[counter];
  if (sent == Clock::time_point{} || arrival < sent) return;
  latencies_ms_.push_back(std::chrono::duration<double, std::milli>(arrival - sent).count());
  if (latencies_ms_.size() == samples_ + 20) report();  // the first 20 warm the path up
}

void LatencyProbe::report() {
  std::vector<double> v(latencies_ms_.begin() + 20, latencies_ms_.end());
  std::sort(v.begin(), v.end());
  auto at = [&](double q) { return v[std::min(v.size() - 1, static_cast<size_t>(q * v.size()))]; };
  char line[256];
  std::snprintf(line, sizeof line, "%-44s n=%zu  p50 %.3f ms  p99 %.3f ms  max %.3f ms",
                label_.c_str(), v.size(), at(0.50), at(0.99), v.back());
  std::printf("%s\n", line);
  std::fflush(stdout);
  if (!output_.empty()) std::ofstream(output_, std::ios::app) << line << "\n";
  done_ = true;
}

}  // namespace k40t::bench
