// k40t monitor: live decode of a link (or of a capture file), one human line per frame, counters
// at the end (Ctrl-C / SIGTERM on a link, end of file for a capture).
#include <csignal>
#include <cstdio>
#include <ctime>
#include <mutex>
#include <string>

#include "command.h"
#include "frame_text.h"
#include "input.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::tool {

namespace {

std::string wall_clock() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  tm local{};
  localtime_r(&now.tv_sec, &local);
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%02d:%02d:%02d.%03ld", local.tm_hour, local.tm_min,
                local.tm_sec, now.tv_nsec / 1000000);
  return buffer;
}

// Prints one line per frame and counts the frames whose payload did not decode.
class FramePrinter {
 public:
  explicit FramePrinter(const protocol::CodecOptions& codec) : codec_(codec) {}
  void print(const std::string& when, const protocol::FrameView& frame) {
    bool decoded = false;
    const std::string line = frame_summary(frame, codec_, &decoded);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!decoded && protocol::is_known_id(frame.header.message_id)) ++undecodable_;
    std::printf("%s %s\n", when.c_str(), line.c_str());
    std::fflush(stdout);
  }
  uint64_t undecodable() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return undecodable_;
  }

 private:
  const protocol::CodecOptions codec_;
  mutable std::mutex mutex_;
  uint64_t undecodable_ = 0;
};

int monitor_file(const std::string& path, const WireOptions& wire) {
  Result<std::vector<uint8_t>> bytes = read_binary_file(path);
  if (!bytes) {
    std::fprintf(stderr, "k40t monitor: %s\n", bytes.error().c_str());
    return kExitFailed;
  }
  session::Dispatcher dispatcher(wire.crc_coverage, wire.codec);
  FramePrinter printer(wire.codec);
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

// Waits for SIGINT/SIGTERM. On udp:// with nothing received after kUdpHintAfter, says why that is
// likely: a UDP pod, and k40t_sim --link udp://, answer the peer that last wrote to them, and
// monitor never writes.
int wait_with_udp_hint(const sigset_t& stop_signals, const std::string& url,
                       const transport::Transport& link) {
  constexpr time_t kUdpHintAfter = 2;
  if (url.rfind("udp://", 0) == 0) {
    const timespec timeout{kUdpHintAfter, 0};
    const int early = sigtimedwait(&stop_signals, nullptr, &timeout);
    if (early > 0) return early;
    if (link.stats().bytes_received == 0) {
      std::fprintf(stderr,
                   "k40t monitor: nothing received from %s in %lld s: over UDP the pod (and "
                   "k40t_sim --link udp://) sends only to the peer that last wrote to it, and "
                   "monitor only listens; watch the driver's raw/rx topic, or use a serial or tcp "
                   "link\n",
                   url.c_str(), static_cast<long long>(kUdpHintAfter));
    }
  }
  int signal_number = 0;
  sigwait(&stop_signals, &signal_number);
  return signal_number;
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
  FramePrinter printer(wire.codec);
  dispatcher.on_frame(
      [&](const protocol::FrameView& frame) { printer.print(wall_clock(), frame); });
  transport::Transport& t = *link.value();
  t.set_receive_callback([&](const uint8_t* data, size_t size) { dispatcher.feed(data, size); });
  t.set_state_callback([&](transport::LinkState state, const std::string& reason) {
    if (state == transport::LinkState::kConnected) dispatcher.reset();  // a new byte stream
    std::fprintf(stderr, "k40t monitor: %s %s%s%s\n", url.c_str(), transport::to_string(state),
                 reason.empty() ? "" : ": ", reason.c_str());
  });
  const Status opened = t.open();
  if (!opened) {
    std::fprintf(stderr, "k40t monitor: %s\n", opened.message().c_str());
    return kExitFailed;
  }
  int signal_number = wait_with_udp_hint(stop_signals, url, t);
  t.close();
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
  // A URL has a scheme; anything else is a capture file.
  if (source.find("://") != std::string::npos) return monitor_link(self, source, wire.value());
  return monitor_file(source, wire.value());
}

}  // namespace

const Command& monitor_command() {
  static const Command command{
      "monitor",
      "monitor URL|FILE [options]",
      "live decode of a link or a capture file, one line per frame",
      "Decodes every frame from a link URL (serial:///dev/ttyUSB0?baud=115200, udp://...,\n"
      "tcp://..., pty://...) or a binary capture FILE and prints one line per frame: time\n"
      "(byte offset '@N' for a file), message name, source>destination, sequence number and\n"
      "the decoded fields. It only listens: nothing is sent. On a link it runs until Ctrl-C or\n"
      "SIGTERM; then, or at the end of a file, the counters go to stderr.",
      {kCrcCoverageOption, kAckByteOrderOption},
      &run_monitor};
  return command;
}

}  // namespace k40t::tool
