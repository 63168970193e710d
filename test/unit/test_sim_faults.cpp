// Fault injection of the simulator: what each fault does to the bytes, the control language,
// the control socket, the capture files, and the disconnecting transport.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <bitset>
#include <fstream>
#include <iterator>
#include <vector>

#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/parser.h"
#include "k40t_driver/sim/capture_writer.h"
#include "k40t_driver/sim/control_commands.h"
#include "k40t_driver/sim/control_server.h"
#include "k40t_driver/sim/fault_injector.h"
#include "k40t_driver/sim/faulty_transport.h"
#include "sim_control_target.h"

namespace k40t::sim {
namespace {

using protocol::CrcCoverage;

std::vector<uint8_t> sample_frame(uint8_t sequence,
                                  CrcCoverage coverage = CrcCoverage::kHeaderExcluded) {
  protocol::FrameHeader header;
  header.destination = protocol::kHostAddress;
  header.source = protocol::kCameraAddress;
  header.sequence = sequence;
  header.message_id = 0x000003;
  const uint8_t payload[16] = {1, 0, 0, 5, 5, 0, 5, 3, 0, 0x66, 0x19, 0x66, 0x19, 0, 0, 0};
  auto frame = protocol::encode_frame(header, payload, sizeof payload, coverage);
  EXPECT_TRUE(frame) << frame.error();
  return std::vector<uint8_t>(frame->data(), frame->data() + frame->size());
}

// Parses bytes, returning the good frames' sequence numbers.
std::vector<uint8_t> sequences_of(const std::vector<uint8_t>& bytes,
                                  protocol::FrameParser& parser) {
  std::vector<uint8_t> sequences;
  parser.feed(bytes.data(), bytes.size(),
              [&](const protocol::FrameView& f) { sequences.push_back(f.header.sequence); });
  return sequences;
}

TEST(SimFaults, NoFaultsLeaveFramesAlone) {
  FaultInjector faults;
  const auto frame = sample_frame(7);
  EXPECT_EQ(faults.outgoing(frame.data(), frame.size()), frame);
}

TEST(SimFaults, CorruptionFlipsOneBitPerHitByte) {
  FaultInjector faults(3);
  FaultSettings settings;
  settings.corrupt_rate = 1.0;
  faults.set_settings(settings);
  const auto frame = sample_frame(7);
  const auto wire = faults.outgoing(frame.data(), frame.size());
  ASSERT_EQ(wire.size(), frame.size());
  for (size_t i = 0; i < frame.size(); ++i)
    EXPECT_EQ(std::bitset<8>(wire[i] ^ frame[i]).count(), 1u) << i;
  EXPECT_EQ(faults.counters().bytes_corrupted, frame.size());
  protocol::FrameParser parser(CrcCoverage::kHeaderExcluded);
  EXPECT_TRUE(sequences_of(wire, parser).empty());
}

TEST(SimFaults, GarbageGoesBeforeTheFrameAndHasNoStx) {
  FaultInjector faults(5);
  FaultSettings settings;
  settings.garbage_rate = 1.0;
  settings.garbage_max_bytes = 8;
  faults.set_settings(settings);
  const auto frame = sample_frame(9);
  size_t total_garbage = 0;
  protocol::FrameParser parser(CrcCoverage::kHeaderExcluded);
  for (int i = 0; i < 50; ++i) {
    const auto wire = faults.outgoing(frame.data(), frame.size());
    ASSERT_GT(wire.size(), frame.size());
    ASSERT_LE(wire.size(), frame.size() + 8);
    const size_t garbage = wire.size() - frame.size();
    total_garbage += garbage;
    for (size_t k = 0; k < garbage; ++k) EXPECT_NE(wire[k], protocol::kStx);
    EXPECT_TRUE(std::equal(frame.begin(), frame.end(), wire.begin() + static_cast<long>(garbage)));
    EXPECT_EQ(sequences_of(wire, parser).size(), 1u);
  }
  EXPECT_EQ(parser.stats().bytes_discarded, total_garbage);
  EXPECT_EQ(faults.counters().garbage_bytes, total_garbage);
}

TEST(SimFaults, SequenceJumpRenumbersWithAValidChecksum) {
  for (CrcCoverage coverage : {CrcCoverage::kHeaderExcluded, CrcCoverage::kWholeFrame}) {
    FaultInjector faults(1, coverage);
    protocol::FrameParser parser(coverage);
    std::vector<uint8_t> seen;
    for (uint8_t seq = 0; seq < 3; ++seq) {
      const auto frame = sample_frame(seq, coverage);
      for (uint8_t s : sequences_of(faults.outgoing(frame.data(), frame.size()), parser))
        seen.push_back(s);
    }
    faults.jump_sequence(5);
    for (uint8_t seq = 3; seq < 6; ++seq) {
      const auto frame = sample_frame(seq, coverage);
      for (uint8_t s : sequences_of(faults.outgoing(frame.data(), frame.size()), parser))
        seen.push_back(s);
    }
    EXPECT_EQ(seen, (std::vector<uint8_t>{0, 1, 2, 8, 9, 10}));
    EXPECT_EQ(parser.stats().sequence_gaps, 1u);
    EXPECT_EQ(parser.stats().frames_lost, 5u);
  }
}

TEST(SimFaults, SilenceSwallowsFramesForItsDuration) {
  FaultInjector faults;
  const auto now = SteadyClock::now();
  faults.silence_for(std::chrono::milliseconds(500), now);
  const auto frame = sample_frame(1);
  EXPECT_TRUE(
      faults.outgoing(frame.data(), frame.size(), now + std::chrono::milliseconds(499)).empty());
  EXPECT_EQ(faults.outgoing(frame.data(), frame.size(), now + std::chrono::milliseconds(500)),
            frame);
  EXPECT_EQ(faults.counters().frames_silenced, 1u);
}

TEST(SimFaults, AckDecisionsFollowTheRates) {
  FaultInjector faults(11);
  EXPECT_FALSE(faults.drop_ack());
  EXPECT_EQ(faults.ack_delay().count(), 0);
  FaultSettings settings;
  settings.drop_ack_rate = 0.5;
  settings.delay_ack_ms = 250;
  faults.set_settings(settings);
  int dropped = 0;
  for (int i = 0; i < 1000; ++i) dropped += faults.drop_ack() ? 1 : 0;
  EXPECT_GT(dropped, 400);
  EXPECT_LT(dropped, 600);
  EXPECT_EQ(faults.ack_delay().count(), 250);
  EXPECT_EQ(faults.counters().acks_dropped, static_cast<uint64_t>(dropped));
}

TEST(SimFaults, TheSameSeedMisbehavesTheSameWay) {
  FaultSettings settings;
  settings.corrupt_rate = 0.1;
  settings.garbage_rate = 0.3;
  FaultInjector a(42), b(42);
  a.set_settings(settings);
  b.set_settings(settings);
  const auto frame = sample_frame(1);
  for (int i = 0; i < 20; ++i)
    EXPECT_EQ(a.outgoing(frame.data(), frame.size()), b.outgoing(frame.data(), frame.size()));
}

// ---- control language -----------------------------------------------------------------------
using testing::FakeTarget;

TEST(SimControl, CommandsChangeTheFaults) {
  FakeTarget target;
  EXPECT_EQ(execute_control_command("corrupt 0.25", target).rfind("ok", 0), 0u);
  EXPECT_DOUBLE_EQ(target.faults_.settings().corrupt_rate, 0.25);
  EXPECT_EQ(execute_control_command("garbage 0.5 4", target).rfind("ok", 0), 0u);
  EXPECT_EQ(target.faults_.settings().garbage_max_bytes, 4u);
  EXPECT_EQ(execute_control_command("drop-acks 1", target).rfind("ok", 0), 0u);
  EXPECT_DOUBLE_EQ(target.faults_.settings().drop_ack_rate, 1);
  EXPECT_EQ(execute_control_command("delay-acks 400 0.5", target).rfind("ok", 0), 0u);
  EXPECT_DOUBLE_EQ(target.faults_.settings().delay_ack_ms, 400);
  EXPECT_DOUBLE_EQ(target.faults_.settings().delay_ack_rate, 0.5);
  EXPECT_EQ(execute_control_command("disconnect 1.5", target).rfind("ok", 0), 0u);
  EXPECT_EQ(target.disconnected_for.count(), 1500);
  EXPECT_EQ(execute_control_command("silence 2", target).rfind("ok", 0), 0u);
  EXPECT_TRUE(target.faults_.silenced());
  EXPECT_EQ(execute_control_command("seq-jump 3", target).rfind("ok", 0), 0u);
  EXPECT_EQ(target.faults_.counters().sequence_jumps, 1u);
  EXPECT_EQ(execute_control_command("clear", target).rfind("ok", 0), 0u);
  EXPECT_DOUBLE_EQ(target.faults_.settings().drop_ack_rate, 0);
  EXPECT_FALSE(target.faults_.silenced());
  EXPECT_EQ(execute_control_command("status", target), "ok fine");
}

TEST(SimControl, CommandsChangeThePod) {
  FakeTarget target;
  EXPECT_EQ(execute_control_command("sd absent", target), "ok sd absent");
  EXPECT_FALSE(target.pod.camera().sd().present());
  EXPECT_EQ(execute_control_command("sd insert", target), "ok sd normal");
  EXPECT_EQ(execute_control_command("sd fill", target), "ok sd full");
  EXPECT_EQ(execute_control_command("self-test 0x7", target).rfind("ok", 0), 0u);
  EXPECT_EQ(target.pod.self_test(), 0x07);
  EXPECT_EQ(execute_control_command("ground-height 80", target).rfind("ok", 0), 0u);
  EXPECT_DOUBLE_EQ(target.pod.world().config().ground_height_m, 80);
  EXPECT_EQ(execute_control_command("photos", target), "ok 0 photos");
}

TEST(SimControl, BadCommandsGetAReadableError) {
  FakeTarget target;
  EXPECT_EQ(execute_control_command("corrupt 2", target), "error: RATE must be 0..1, got 2");
  EXPECT_EQ(execute_control_command("corrupt lots", target),
            "error: RATE must be a number, got 'lots'");
  EXPECT_EQ(execute_control_command("corrupt", target), "error: usage: corrupt RATE");
  EXPECT_EQ(execute_control_command("explode", target),
            "error: unknown command 'explode'; try 'help'");
  EXPECT_EQ(execute_control_command("", target), "error: empty command; try 'help'");
  EXPECT_EQ(
      execute_control_command("sd wet", target).rfind("error: sd: unknown condition 'wet'", 0), 0u);
  EXPECT_EQ(execute_control_command("self-test 0x1F", target),
            "error: MASK must be 0..0x0F, got '0x1F'");
  EXPECT_NE(execute_control_command("help", target).find("disconnect SECONDS"), std::string::npos);
}

// ---- control socket -------------------------------------------------------------------------
std::string exchange(int fd, const std::string& line) {
  EXPECT_EQ(::send(fd, line.data(), line.size(), 0), static_cast<ssize_t>(line.size()));
  std::string reply;
  char c;
  while (::recv(fd, &c, 1, 0) == 1 && c != '\n') reply += c;
  return reply;
}

TEST(SimControlServer, AnswersLinesOverLoopbackTcp) {
  ControlServer server;
  ASSERT_TRUE(
      server.start("tcp:127.0.0.1:0", [](const std::string& line) { return "echo " + line; }));
  ASSERT_GT(server.port(), 0);
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(server.port()));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  EXPECT_EQ(exchange(fd, "status\n"), "echo status");
  EXPECT_EQ(exchange(fd, "a\r\nb\n"), "echo a");
  std::string second;
  char c;
  while (::recv(fd, &c, 1, 0) == 1 && c != '\n') second += c;
  EXPECT_EQ(second, "echo b");
  ::close(fd);
  server.stop();
}

TEST(SimControlServer, AnswersOverAUnixSocket) {
  const std::string path = ::testing::TempDir() + "k40t_sim_control_test.sock";
  ControlServer server;
  ASSERT_TRUE(server.start("unix:" + path, [](const std::string& line) { return "got " + line; }));
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::snprintf(addr.sun_path, sizeof addr.sun_path, "%s", path.c_str());
  ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  EXPECT_EQ(exchange(fd, "help\n"), "got help");
  ::close(fd);
  server.stop();
  EXPECT_NE(::access(path.c_str(), F_OK), 0);  // removed on stop
}

TEST(SimControlServer, BadEndpointsAreNamed) {
  ControlServer server;
  const Status bad = server.start("tcp:10.0.0.1:99", [](const std::string&) { return ""; });
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.message().find("tcp:10.0.0.1:99"), std::string::npos) << bad.message();
  EXPECT_FALSE(server.start("70000", [](const std::string&) { return ""; }));
}

// ---- capture --------------------------------------------------------------------------------
std::vector<uint8_t> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

TEST(SimCapture, WritesEachDirectionToItsOwnRawFile) {
  const std::string prefix = ::testing::TempDir() + "k40t_capture_test";
  {
    auto capture = CaptureWriter::open(prefix);
    ASSERT_TRUE(capture) << capture.error();
    const uint8_t out1[] = {0xFD, 1, 2};
    const uint8_t out2[] = {3};
    const uint8_t in[] = {9, 8};
    (*capture)->sent(out1, 3);
    (*capture)->received(in, 2);
    (*capture)->sent(out2, 1);
    EXPECT_EQ((*capture)->bytes_sent(), 4u);
  }
  EXPECT_EQ(read_file(prefix + ".tx.bin"), (std::vector<uint8_t>{0xFD, 1, 2, 3}));
  EXPECT_EQ(read_file(prefix + ".rx.bin"), (std::vector<uint8_t>{9, 8}));
  const auto bad = CaptureWriter::open("/nonexistent-dir/x");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("/nonexistent-dir/x.tx.bin"), std::string::npos);
}

// ---- the disconnecting transport ------------------------------------------------------------
class RecordingTransport : public transport::Transport {
 public:
  explicit RecordingTransport(std::vector<std::vector<uint8_t>>& sent, int& closes)
      : sent_(sent), closes_(closes) {}
  Status open() override {
    state_ = transport::LinkState::kConnected;
    return Status::ok();
  }
  void close() override {
    ++closes_;
    state_ = transport::LinkState::kClosed;
  }
  Status send(const uint8_t* data, size_t size) override {
    sent_.emplace_back(data, data + size);
    return Status::ok();
  }
  transport::LinkState state() const override { return state_; }
  transport::LinkStats stats() const override {
    transport::LinkStats s;
    s.connects = 1;
    return s;
  }
  std::string url() const override { return "fake://"; }
  void deliver(const uint8_t* data, size_t size) { on_receive_(data, size); }

 private:
  std::vector<std::vector<uint8_t>>& sent_;
  int& closes_;
  transport::LinkState state_ = transport::LinkState::kClosed;
};

TEST(SimFaultyTransport, DisconnectsAndReopensFromTheFactory) {
  std::vector<std::vector<uint8_t>> sent;
  int closes = 0;
  int made = 0;
  RecordingTransport* latest = nullptr;
  FaultInjector faults;
  const std::string prefix = ::testing::TempDir() + "k40t_faulty_transport_test";
  auto capture = CaptureWriter::open(prefix);
  ASSERT_TRUE(capture);
  FaultyTransport link(
      [&]() -> Result<std::unique_ptr<transport::Transport>> {
        ++made;
        auto t = std::make_unique<RecordingTransport>(sent, closes);
        latest = t.get();
        return std::unique_ptr<transport::Transport>(std::move(t));
      },
      "fake://", faults, capture->get());
  std::vector<uint8_t> received;
  link.set_receive_callback(
      [&](const uint8_t* d, size_t n) { received.insert(received.end(), d, d + n); });
  ASSERT_TRUE(link.open());
  EXPECT_EQ(link.state(), transport::LinkState::kConnected);

  const uint8_t bytes[] = {1, 2, 3};
  ASSERT_TRUE(link.send(bytes, 3));
  latest->deliver(bytes, 2);
  EXPECT_EQ(received.size(), 2u);
  EXPECT_EQ((*capture)->bytes_sent(), 3u);
  EXPECT_EQ((*capture)->bytes_received(), 2u);

  const auto now = SteadyClock::now();
  link.disconnect_for(std::chrono::milliseconds(1000), now);
  EXPECT_EQ(closes, 1);
  EXPECT_EQ(link.state(), transport::LinkState::kReconnecting);
  EXPECT_FALSE(link.send(bytes, 3));
  link.poll(now + std::chrono::milliseconds(999));
  EXPECT_EQ(made, 1);
  link.poll(now + std::chrono::milliseconds(1000));
  EXPECT_EQ(made, 2);
  EXPECT_EQ(link.state(), transport::LinkState::kConnected);
  EXPECT_TRUE(link.send(bytes, 3));
  EXPECT_EQ(sent.size(), 2u);
  EXPECT_EQ(link.stats().connects, 2u);  // the closed link's figures are kept
  EXPECT_EQ(faults.counters().disconnects, 1u);
  link.close();
}

}  // namespace
}  // namespace k40t::sim
