// k40t_topic_monitor, run as `k40t monitor ros:///NAMESPACE`: a running driver's link as
// `k40t monitor` shows a device, but from the driver's raw/rx and raw/tx topics, so the device
// stays the driver's alone (a second reader on a serial line takes bytes from the first). Needs
// roscpp, hence its own program, which the ROS-free `k40t` runs.
#include <ros/ros.h>

#include <cstdio>
#include <string>
#include <vector>

#include "command.h"  // tools/k40t: argument parsing shared with the other subcommands
#include "frame_printer.h"
#include "frame_text.h"
#include "k40t_driver/Frame.h"
#include "k40t_driver/session/dispatcher.h"

namespace k40t::tool {
namespace {

const char* const kUsage =
    "usage: k40t monitor ros:///NAMESPACE [--crc-coverage ..] [--ack-byte-order ..]";

// One direction's frames: its own dispatcher (each topic is a stream of whole frames).
class DirectionMonitor {
 public:
  DirectionMonitor(const char* name, const WireOptions& wire, FramePrinter& printer)
      : name_(name), dispatcher_(wire.crc_coverage, wire.codec) {
    dispatcher_.on_frame([this, &printer](const protocol::FrameView& frame) {
      printer.print(stamp_ + " " + name_, frame);
    });
  }

  void feed(const k40t_driver::Frame& frame) {
    stamp_ = time_of_day_text(
        timespec{static_cast<time_t>(frame.stamp.sec), static_cast<long>(frame.stamp.nsec)});
    dispatcher_.feed_frame(frame.data.data(), frame.data.size());
  }

  const session::Dispatcher& dispatcher() const { return dispatcher_; }

 private:
  const std::string name_;
  session::Dispatcher dispatcher_;
  std::string stamp_;
};

int run(int argc, char** argv) {
  ros::init(argc, argv, "k40t_topic_monitor", ros::init_options::AnonymousName);
  const std::vector<OptionSpec> specs = {kCrcCoverageOption, kAckByteOrderOption};
  Result<ParsedArgs> args = parse_args(std::vector<std::string>(argv + 1, argv + argc), specs);
  if (!args || args->positional.size() != 1) {
    std::fprintf(stderr, "k40t monitor: %s\n%s\n",
                 args ? "give one namespace" : args.error().c_str(), kUsage);
    return kExitUsage;
  }
  Result<WireOptions> wire = wire_options(args.value());
  if (!wire) {
    std::fprintf(stderr, "k40t monitor: %s\n", wire.error().c_str());
    return kExitUsage;
  }
  std::string ns = args->positional[0];
  if (ns.empty()) ns = "/";
  ros::NodeHandle nh(ns);
  FramePrinter printer(wire->codec);
  DirectionMonitor rx("rx", wire.value(), printer);
  DirectionMonitor tx("tx", wire.value(), printer);
  // Deep queues: a burst (the settings read-back) must not drop lines while stdout is slow.
  ros::Subscriber rx_sub = nh.subscribe<k40t_driver::Frame>(
      "raw/rx", 1000, [&rx](const k40t_driver::Frame::ConstPtr& frame) { rx.feed(*frame); });
  ros::Subscriber tx_sub = nh.subscribe<k40t_driver::Frame>(
      "raw/tx", 1000, [&tx](const k40t_driver::Frame::ConstPtr& frame) { tx.feed(*frame); });
  std::fprintf(stderr, "k40t monitor: watching %s and %s (Ctrl-C stops)\n",
               rx_sub.getTopic().c_str(), tx_sub.getTopic().c_str());
  ros::spin();  // one thread: the lines of both topics never interleave
  std::fprintf(stderr, "k40t monitor: stopped; rx: %s; tx: %s\n",
               counters_text(rx.dispatcher().stats(), 0).c_str(),
               counters_text(tx.dispatcher().stats(), 0).c_str());
  return kExitOk;
}

}  // namespace
}  // namespace k40t::tool

int main(int argc, char** argv) {
  return k40t::tool::run(argc, argv);
}
