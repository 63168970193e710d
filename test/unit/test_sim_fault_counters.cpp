// Each fault of the simulated pod, seen by a client built only on the core library: the fault
// shows up as the counter a driver's diagnostics would raise.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "sim_link_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using testing::SimLink;
using namespace std::chrono_literals;

p::ParserStats parser_of(SimLink& link) {
  return link.client().stats().parser;
}

// Turns one fault of the simulated pod on.
template <class Field, class Value>
void set_fault(SimLink& link, Field FaultSettings::*field, Value value) {
  FaultSettings faults;
  faults.*field = value;
  link.server().faults().set_settings(faults);
}

// A client that gives up on an ACK after 150 ms and retries `retries` times.
session::SessionOptions impatient_client(int retries) {
  session::SessionOptions client;
  client.ack_timeout = 150ms;
  client.retries = retries;
  return client;
}

TEST(SimFaultCounters, CorruptionShowsAsChecksumErrorsAndDiscardedBytes) {
  SimLink link;
  set_fault(link, &FaultSettings::corrupt_rate, 0.01);  // a 32-byte frame is hit one time in four
  ASSERT_TRUE(SimLink::wait_for([&] { return parser_of(link).checksum_errors >= 3; }));
  const p::ParserStats stats = parser_of(link);
  EXPECT_GT(stats.bytes_discarded, 0u);
  EXPECT_GT(stats.frames_good, 0u);  // most frames still get through
  EXPECT_GT(link.server().faults().counters().bytes_corrupted, 0u);
}

TEST(SimFaultCounters, GarbageIsDiscardedByteForByteAndCostsNoFrame) {
  SimLink link;
  const p::ParserStats before = parser_of(link);
  const size_t attitude_before = link.count(p::GimbalAttitude::kId);
  set_fault(link, &FaultSettings::garbage_rate, 0.5);
  ASSERT_TRUE(
      SimLink::wait_for([&] { return link.server().faults().counters().garbage_bursts >= 10; }));
  link.server().faults().clear();
  const uint64_t garbage = link.server().faults().counters().garbage_bytes;
  // Once the last burst has arrived, every garbage byte has been discarded, and nothing else.
  EXPECT_TRUE(SimLink::wait_for(
      [&] { return parser_of(link).bytes_discarded - before.bytes_discarded == garbage; }));
  const p::ParserStats after = parser_of(link);
  EXPECT_EQ(after.bytes_discarded - before.bytes_discarded, garbage);
  EXPECT_EQ(after.checksum_errors, before.checksum_errors);  // garbage has no STX: no false frames
  EXPECT_EQ(after.sequence_gaps, before.sequence_gaps);      // and no frame was lost
  EXPECT_GT(link.count(p::GimbalAttitude::kId), attitude_before);
}

TEST(SimFaultCounters, DroppedAcksShowAsRetriesThenATimeout) {
  SimLink link({}, impatient_client(2));
  set_fault(link, &FaultSettings::drop_ack_rate, 1.0);
  const session::SessionStats before = link.client().stats();
  EXPECT_EQ(link.send(p::CameraVersionRequest{}), p::ResponseCode::kTimeout);
  const session::SessionStats after = link.client().stats();
  EXPECT_EQ(after.ack_timeouts - before.ack_timeouts, 1u);
  EXPECT_EQ(after.retries - before.retries, 2u);
  EXPECT_EQ(link.server().faults().counters().acks_dropped, 3u);  // every attempt reached the pod

  link.server().faults().clear();
  EXPECT_EQ(link.send(p::CameraVersionRequest{}), p::ResponseCode::kOk);
}

TEST(SimFaultCounters, DelayedAcksShowAsRetriesAndLateAcks) {
  // Retries enough for the first ACK (250 ms plus whatever a loaded machine adds) to come back
  // while one of them is outstanding.
  SimLink link({}, impatient_client(10));
  set_fault(link, &FaultSettings::delay_ack_ms, 250);
  const session::SessionStats before = link.client().stats();
  // The first attempt's ACK arrives while a retry is outstanding: the request succeeds late, and
  // the ACK of the retry arrives with nothing waiting for it.
  EXPECT_EQ(link.send(p::CameraVersionRequest{}), p::ResponseCode::kOk);
  EXPECT_TRUE(
      SimLink::wait_for([&] { return link.client().stats().late_acks > before.late_acks; }));
  const session::SessionStats after = link.client().stats();
  EXPECT_GE(after.retries - before.retries, 1u);
  EXPECT_EQ(after.ack_timeouts, before.ack_timeouts);
  EXPECT_GE(link.server().faults().counters().acks_delayed, 2u);
}

TEST(SimFaultCounters, SequenceJumpShowsAsOneGapPerSource) {
  SimLink link;
  // Both sources must have a sequence history before the jump, or a source first heard after it
  // shows no gap (the camera's first 5 Hz report can lag the gimbal's on a loaded machine).
  ASSERT_TRUE(SimLink::wait_for([&] { return link.count(p::ThermalStatus::kId) > 0; }));
  const p::ParserStats before = parser_of(link);
  link.server().faults().jump_sequence(7);
  // The gimbal (0x03) and the camera (0x04) number their frames separately: one gap each.
  ASSERT_TRUE(
      SimLink::wait_for([&] { return parser_of(link).sequence_gaps - before.sequence_gaps >= 2; }));
  std::this_thread::sleep_for(300ms);
  const p::ParserStats after = parser_of(link);
  EXPECT_EQ(after.sequence_gaps - before.sequence_gaps, 2u);
  EXPECT_EQ(after.frames_lost - before.frames_lost, 14u);
  EXPECT_EQ(after.checksum_errors,
            before.checksum_errors);  // renumbered frames carry good checksums
}

TEST(SimFaultCounters, SilenceStopsEveryReportForItsDuration) {
  SimLink link;
  FaultInjector& faults = link.server().faults();
  // Pod-side progress, not the test's sleeps, paces the checks: about 23 frames a second are due
  // (10 Hz attitude among them), and the silence is long enough for a loaded machine.
  const auto swallowed = [&](uint64_t frames) {
    return SimLink::wait_for([&] { return faults.counters().frames_silenced >= frames; });
  };
  faults.silence_for(3000ms);
  ASSERT_TRUE(swallowed(10));  // about 0.4 s in: a frame sent before has arrived by now
  const size_t during = link.count(p::GimbalAttitude::kId);
  ASSERT_TRUE(swallowed(faults.counters().frames_silenced + 14));  // about 0.6 s more
  ASSERT_TRUE(faults.silenced());  // the window checked lies inside the silence
  EXPECT_EQ(link.count(p::GimbalAttitude::kId), during);  // 10 Hz report, nothing for 0.6 s
  EXPECT_TRUE(SimLink::wait_for([&] { return link.count(p::GimbalAttitude::kId) > during; }));
  EXPECT_GT(faults.counters().frames_silenced, 5u);
}

TEST(SimFaultCounters, DisconnectShowsAsALinkLossAndAReconnect) {
  SimLink link;
  const transport::LinkStats before = link.client().stats().link;
  link.server().disconnect_for(800ms);
  ASSERT_TRUE(SimLink::wait_for(
      [&] { return link.client().stats().link.disconnects > before.disconnects; }));
  const size_t during = link.count(p::GimbalAttitude::kId);
  // The pod comes back on the same path; the client reconnects and the reports resume.
  ASSERT_TRUE(
      SimLink::wait_for([&] { return link.client().stats().link.connects > before.connects; }));
  EXPECT_TRUE(SimLink::wait_for([&] { return link.count(p::GimbalAttitude::kId) > during + 5; }));
  EXPECT_EQ(link.send(p::CameraVersionRequest{}), p::ResponseCode::kOk);
  EXPECT_EQ(link.server().faults().counters().disconnects, 1u);
}

TEST(SimFaultCounters, ScheduledFaultsFireFromTheCommandLineOptions) {
  auto options = parse_sim_options({"--seq-jump", "0.5:3"});
  ASSERT_TRUE(options) << options.error();
  SimLink link(*options);
  ASSERT_TRUE(
      SimLink::wait_for([&] { return link.server().faults().counters().sequence_jumps == 1; }));
  EXPECT_TRUE(SimLink::wait_for([&] { return parser_of(link).frames_lost >= 3; }));
}

// One command line over the control socket, its reply line back.
std::string control(int port, const std::string& command) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    ::close(fd);
    return "cannot connect";
  }
  const std::string line = command + "\n";
  (void)!::send(fd, line.data(), line.size(), 0);
  std::string reply;
  char c;
  while (::recv(fd, &c, 1, 0) == 1 && c != '\n') reply += c;
  ::close(fd);
  return reply;
}

TEST(SimFaultCounters, ControlSocketDrivesTheFaults) {
  SimOptions options;
  options.control_endpoint = "tcp:127.0.0.1:0";
  SimLink link(options);
  ASSERT_GT(link.server().control_port(), 0);
  const p::ParserStats before = parser_of(link);
  EXPECT_EQ(control(link.server().control_port(), "seq-jump 5").rfind("ok", 0), 0u);
  EXPECT_TRUE(
      SimLink::wait_for([&] { return parser_of(link).frames_lost - before.frames_lost >= 5; }));
  EXPECT_EQ(control(link.server().control_port(), "sd absent"), "ok sd absent");
  EXPECT_TRUE(link.wait_report<p::CameraSystemStatus>(
      [](const p::CameraSystemStatus& s) { return s.sd_state == p::SdCardState::kMissing; }));
  const std::string status = control(link.server().control_port(), "status");
  EXPECT_NE(status.find("connected"), std::string::npos) << status;
  EXPECT_NE(status.find("seq-jumps=1"), std::string::npos) << status;
  // The settings the rviz panel's test reads back (docs/simulator.md, control socket `status`).
  link.server().with_model([](PodModel& pod) {
    pod.thermal().settings().reported.palette = protocol::Palette::kIceFire;  // 13
    pod.camera().settings().image_mode = 7;
  });
  const std::string settings = control(link.server().control_port(), "status");
  EXPECT_NE(settings.find(" palette 13 image-mode 7 "), std::string::npos) << settings;
}

}  // namespace
}  // namespace k40t::sim
