// k40t_latency_probe: the probe as a node of its own, i.e. another process than the driver.
#include <ros/ros.h>

#include "latency_probe.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "latency_probe");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  k40t::bench::LatencyProbe probe(nh, private_nh);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  while (ros::ok() && !probe.done()) ros::WallDuration(0.05).sleep();
  ros::shutdown();
  return 0;
}
