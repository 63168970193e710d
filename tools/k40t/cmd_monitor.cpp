// k40t monitor: live decode of a link (or of a capture file), one human line per frame, counters
// at the end (Ctrl-C / SIGTERM on a link, end of file for a capture).
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>

#include "command.h"
#include "frame_printer.h"
#include "frame_text.h"
#include "input.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::tool {

namespace {

int monitor_file(const std::string& path, const WireOptions& wire) {
  Result<std::vector<uint8_t>> bytes = read_binary_file(path);
  if (!bytes) {
    std::fprintf(stderr, "k40t monitor: %s\n", bytes.error().c_str());
    return kExitFailed;
  }
  session::Dispatcher dispatcher(wire.crc_coverage, wire.codec);
  FramePrinter printer(wire.codec, &dispatcher.ack_order());
  CaptureCursor cursor;
  dispatcher.on_frame([&](const protocol::FrameView& frame) {
    char offset[24];
    std::snprintf(offset, sizeof(offset), "@%06llu",
                  static_cast<unsigned long long>(cursor.frame_offset(frame)));
    printer.print(offset, frame);
  });
  feed_capture(dispatcher, bytes.value(), cursor);
  std::fprintf(stderr, "k40t monitor: %s: %s\n", path.c_str(),
               counters_text(dispatcher.stats(), printer.undecodable()).c_str());
  return kExitOk;
}

constexpr const char* kRosScheme = "ros://";

constexpr const char* kBusyHint =
    "k40t monitor: to watch a running driver's link, read its topics instead: "
    "k40t monitor ros:///NAMESPACE (e.g. ros:///k40t)";

// The stop signal that arrived, or 0 as soon as `given_up` is set (the device is busy). On udp://
// with nothing received after kUdpHintAfter, says why that is likely: a UDP pod, and k40t_sim
// --link udp://, answer the peer that last wrote to them, and monitor never writes.
int wait_for_stop(const sigset_t& stop_signals, const std::atomic<bool>& given_up,
                  const std::string& url, const transport::Transport& link) {
  constexpr auto kUdpHintAfter = std::chrono::seconds(2);
  const auto started = std::chrono::steady_clock::now();
  bool hint_due = url.rfind("udp://", 0) == 0;
  const timespec poll_period{0, 50 * 1000 * 1000};
  while (!given_up) {
    const int signal_number = sigtimedwait(&stop_signals, nullptr, &poll_period);
    if (signal_number > 0) return signal_number;
    if (hint_due && std::chrono::steady_clock::now() - started >= kUdpHintAfter) {
      hint_due = false;
      if (link.stats().bytes_received == 0) {
        std::fprintf(stderr,
                     "k40t monitor: nothing received from %s in %lld s: over UDP the pod (and "
                     "k40t_sim --link udp://) sends only to the peer that last wrote to it, and "
                     "monitor only listens; watch the driver's raw/rx topic, or use a serial or "
                     "tcp link\n",
                     url.c_str(), static_cast<long long>(kUdpHintAfter.count()));
      }
    }
  }
  return 0;
}

int monitor_link(const Command& self, const std::string& url, const WireOptions& wire) {
  Result<std::unique_ptr<transport::Transport>> link = transport::make_transport(url);
  if (!link) return usage_error(self, link.error());
  // Block the stop signals before the transport starts its thread (which inherits the mask), and
  // wait for them here: no handler, no global flag.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  session::Dispatcher dispatcher(wire.crc_coverage, wire.codec);
  FramePrinter printer(wire.codec, &dispatcher.ack_order());
  dispatcher.on_frame(
      [&](const protocol::FrameView& frame) { printer.print(wall_clock(), frame); });
  transport::Transport& t = *link.value();
  t.set_receive_callback([&](const uint8_t* data, size_t size) { dispatcher.feed(data, size); });
  std::atomic<bool> busy{false};
  t.set_state_callback([&](transport::LinkState state, const std::string& reason) {
    if (busy) return;  // said why; the rest is the close
    if (state == transport::LinkState::kConnected) dispatcher.reset();  // a new byte stream
    // Another program reads this device (the driver, usually): reading beside it would take
    // its bytes, so give up at once and say who holds it.
    if (state == transport::LinkState::kReconnecting && t.stats().device_busy) {
      std::fprintf(stderr, "k40t monitor: %s\n%s\n", reason.c_str(), kBusyHint);
      busy = true;
      return;
    }
    std::fprintf(stderr, "k40t monitor: %s %s%s%s\n", url.c_str(), transport::to_string(state),
                 reason.empty() ? "" : ": ", reason.c_str());
  });
  const Status opened = t.open();
  if (!opened) {
    std::fprintf(stderr, "k40t monitor: %s\n", opened.message().c_str());
    return kExitFailed;
  }
  const int signal_number = wait_for_stop(stop_signals, busy, url, t);
  t.close();
  if (signal_number == 0) return kExitFailed;  // busy
  const transport::LinkStats link_stats = t.stats();
  std::fprintf(stderr, "k40t monitor: stopped by %s; %s; %llu bytes received\n",
               signal_number == SIGINT ? "SIGINT" : "SIGTERM",
               counters_text(dispatcher.stats(), printer.undecodable()).c_str(),
               static_cast<unsigned long long>(link_stats.bytes_received));
  return kExitOk;
}

int run_monitor(const Command& self, const ParsedArgs& args) {
  Result<WireOptions> wire = wire_options(args);
  if (!wire) return usage_error(self, wire.error());
  if (args.positional.size() != 1) return usage_error(self, "give one URL or capture FILE");
  const std::string& source = args.positional[0];
  // A running driver's link, from its raw/rx and raw/tx topics (the ROS build's program).
  if (source.rfind(kRosScheme, 0) == 0) {
    std::vector<std::string> forwarded{source.substr(std::string(kRosScheme).size())};
    for (const auto& [option, value] : args.options)
      forwarded.insert(forwarded.end(), {option, value});
    return run_ros_program("k40t_topic_monitor", "monitor", program_path(), forwarded);
  }
  // A URL has a scheme; anything else is a capture file.
  if (source.find("://") != std::string::npos) return monitor_link(self, source, wire.value());
  return monitor_file(source, wire.value());
}

}  // namespace

const Command& monitor_command() {
  static const Command command{
      "monitor",
      "monitor URL|ros:///NAMESPACE|FILE [options]",
      "live decode of a link, a running driver's link or a capture file, one line per frame",
      "Decodes every frame from a link URL (serial:///dev/ttyUSB0?baud=115200, udp://...,\n"
      "tcp://..., pty://...) or a binary capture FILE and prints one line per frame: time\n"
      "(byte offset '@N' for a file), message name, source>destination, sequence number and\n"
      "the decoded fields. It only listens: nothing is sent. On a link it runs until Ctrl-C or\n"
      "SIGTERM; then, or at the end of a file, the counters go to stderr.\n"
      "A serial device is opened exclusively: one the driver (or any program) holds is refused\n"
      "at once (exit 1) with the holder's pid and name. To watch a running driver's link, give\n"
      "ros:///NAMESPACE (e.g. ros:///k40t): the frames of its raw/rx and raw/tx topics, marked\n"
      "rx/tx, without touching the device (runs the ROS build's k40t_topic_monitor).",
      {kCrcCoverageOption, kAckByteOrderOption},
      &run_monitor};
  return command;
}

}  // namespace k40t::tool
