// k40t_service_rtt: round trip of a driver service against the simulated pod, beside the time the
// request and its ACK need on a 115200-baud wire. Prints p50/p99/max and the margin over the wire.
//   rosrun k40t_driver k40t_service_rtt _calls:=300 _baud:=115200
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "k40t_driver/SetPalette.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "service_rtt");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  const int calls = private_nh.param("calls", 300);
  const double baud = private_nh.param("baud", 115200.0);
  ros::ServiceClient client =
      nh.serviceClient<k40t_driver::SetPalette>("set_palette", true);  // persistent
  if (!client.waitForExistence(ros::Duration(20.0))) {
    std::fprintf(stderr, "service_rtt: %s not available\n", client.getService().c_str());
    return 1;
  }
  // Until the pod answers (the driver may still be reading its settings), then 10 warm-up calls.
  std::string last_failure;
  auto call = [&](int i, double* elapsed_ms) {
    k40t_driver::SetPalette srv;
    srv.request.palette = static_cast<uint8_t>(1 + i % 20);
    // A persistent connection (no per-call handshake) is dropped after a failure: make a new one.
    if (!client.isValid()) client = nh.serviceClient<k40t_driver::SetPalette>("set_palette", true);
    const auto start = std::chrono::steady_clock::now();
    const bool called = client.call(srv);
    *elapsed_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!called) last_failure = "the service call itself failed";
    if (called && !srv.response.success) last_failure = srv.response.message;
    return called && srv.response.success;
  };
  double elapsed = 0;
  const ros::WallTime ready_deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  while (ros::ok() && !call(0, &elapsed) && ros::WallTime::now() < ready_deadline) {
    ros::WallDuration(0.2).sleep();
  }
  for (int i = 0; i < 10 && ros::ok(); ++i) call(i, &elapsed);
  std::vector<double> ms;
  int failures = 0;
  for (int i = 0; i < calls && ros::ok(); ++i) {
    if (call(i, &elapsed)) {
      ms.push_back(elapsed);
    } else {
      ++failures;
    }
  }
  if (ms.empty()) {
    std::fprintf(stderr, "service_rtt: no successful call (%d failures; last: %s)\n", failures,
                 last_failure.c_str());
    return 1;
  }
  std::sort(ms.begin(), ms.end());
  auto at = [&](double q) {
    return ms[std::min(ms.size() - 1, static_cast<size_t>(q * ms.size()))];
  };
  // 0x000106 request: 12 bytes of frame + 2 of payload; its ACK: 12 + 2. 10 bits per byte.
  const double wire_ms = (14 + 14) * 10.0 / baud * 1000.0;
  std::printf(
      "set_palette round trip (service -> pod -> ACK)  n=%zu  p50 %.3f ms  p99 %.3f ms  max %.3f "
      "ms\n",
      ms.size(), at(0.5), at(0.99), ms.back());
  std::printf(
      "  wire time of request + ACK at %.0f baud: %.3f ms; p99 - wire = %.3f ms (target <= 2 ms); "
      "failures %d\n",
      baud, wire_ms, at(0.99) - wire_ms, failures);
  return 0;
}
