// The session and the k40t tool over a real pseudo-terminal: the simulated pod's side opens
// pty://PATH (a Session in the pod role), the driver's side serial://PATH, as in the demos.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "run_tool.h"
#include "session_test_link.h"
#include "transport_test_support.h"

namespace k40t::test {
namespace {

using namespace std::chrono_literals;
using protocol::FrameView;
using protocol::Payload;

using transport::testing::eventually;

class PtyLink : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = dir_.file("pod");
    Result<std::unique_ptr<transport::Transport>> pod_link =
        transport::make_transport("pty://" + path_);
    ASSERT_TRUE(pod_link) << pod_link.error();
    pod_ = std::make_unique<session::Session>(std::move(pod_link.value()), pod_options());
  }
  void TearDown() override {
    if (host_) host_->stop();
    if (pod_) pod_->stop();
  }
  // After the pod's handlers are registered: the pty, then (optionally) the driver's session,
  // with `before_start` registering its handlers.
  void start(bool with_host = true, session::SessionOptions options = host_options(2000ms, 0),
             const std::function<void(session::Session&)>& before_start = {}) {
    ASSERT_TRUE(pod_->start());
    ASSERT_TRUE(eventually([&] { return pod_->link_state() == transport::LinkState::kConnected; }));
    if (!with_host) return;
    Result<std::unique_ptr<transport::Transport>> host_link =
        transport::make_transport("serial://" + path_);
    ASSERT_TRUE(host_link) << host_link.error();
    host_ = std::make_unique<session::Session>(std::move(host_link.value()), options);
    if (before_start) before_start(*host_);
    ASSERT_TRUE(host_->start());
    ASSERT_TRUE(
        eventually([&] { return host_->link_state() == transport::LinkState::kConnected; }));
  }
  void answer_laser(uint16_t code) {
    pod_->set_request_handler(protocol::LaserRangeRequest::kId, [code](const FrameView&) {
      return std::optional<Payload>(ack_payload(code, {0x00, 0x7B}));  // 12.3 m
    });
  }

  transport::testing::ScratchDir dir_;
  std::string path_;
  std::unique_ptr<session::Session> pod_;
  std::unique_ptr<session::Session> host_;
};

TEST_F(PtyLink, RequestAndAckOverAPty) {
  answer_laser(0);
  start();
  session::AckResult raw;
  Result<protocol::LaserRangeAck> ack = host_->request_typed(protocol::LaserRangeRequest{}, &raw);
  ASSERT_TRUE(ack) << ack.error();
  EXPECT_DOUBLE_EQ(ack->distance_m, 12.3);
  EXPECT_EQ(raw.attempts, 1);
  EXPECT_EQ(host_->stats().link.bytes_sent, 14u);  // one 14-byte frame (section 3.2.5.1)
  EXPECT_EQ(host_->stats().link_state, transport::LinkState::kConnected);
}

TEST_F(PtyLink, ReportsFlowFromThePodToTypedHandlers) {
  Collector<double> yaws;
  start(true, host_options(2000ms, 0), [&](session::Session& host) {
    host.dispatcher().on<protocol::GimbalAttitude>(
        [&](const protocol::GimbalAttitude& a, const FrameView&) { yaws.add(a.yaw_deg); });
  });
  protocol::GimbalAttitude attitude;
  for (int i = 0; i < 5; ++i) {
    attitude.yaw_deg = 10.0 * i;
    ASSERT_TRUE(pod_->send_message(attitude, protocol::kHostAddress));
  }
  ASSERT_TRUE(yaws.wait_for_count(5));
  EXPECT_EQ(yaws.items(), (std::vector<double>{0, 10, 20, 30, 40}));
  EXPECT_EQ(host_->stats().parser.sequence_gaps, 0u);
}

TEST_F(PtyLink, SilentPodTimesOut) {
  start(true, host_options(30ms, 1));
  const session::AckResult r = host_->request(protocol::LaserRangeRequest{});
  EXPECT_TRUE(r.sent);
  EXPECT_FALSE(r.received);
  EXPECT_EQ(r.attempts, 2);
  EXPECT_EQ(host_->stats().ack_timeouts, 1u);
}

TEST_F(PtyLink, K40tSendPrintsTheAckAndExitsZero) {
  answer_laser(0);
  start(false);
  const ToolRun run = run_k40t("send serial://" + path_ + " laser_range enable=1");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "laser_range_ack code=ok_success(0) distance_m=12.3\n");
}

TEST_F(PtyLink, K40tSendExitsOneOnANack) {
  answer_laser(0x0204);  // section 3.3: no SD card
  start(false);
  const ToolRun run = run_k40t("send serial://" + path_ + " laser_range");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("refused by the pod: no SD card (response code 0x0204)"),
            std::string::npos)
      << run.err;
}

TEST_F(PtyLink, K40tSendExitsOneOnATimeout) {
  start(false);  // no handler: the pod stays silent
  const ToolRun run =
      run_k40t("send serial://" + path_ + " 0x000400 --payload '01 00' --timeout 50 --retries 1");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("no ACK for laser_range (0x000400) after 2 attempts"), std::string::npos)
      << run.err;
}

TEST_F(PtyLink, K40tMonitorPrintsLiveFramesAndStopsCleanlyOnSigterm) {
  start(false);
  std::atomic<bool> done{false};
  std::thread reports([&] {
    protocol::GimbalAttitude attitude;
    attitude.pitch_deg = -12.5;
    while (!done) {
      (void)pod_->send_message(attitude, protocol::kHostAddress);
      std::this_thread::sleep_for(20ms);
    }
  });
  // timeout(1) sends SIGTERM after 2 s; --preserve-status passes k40t's own exit code on.
  const ToolRun run = run_shell("timeout --preserve-status -s TERM 2 '" + k40t_path() +
                                "' monitor serial://" + path_);
  done = true;
  reports.join();
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("gimbal_attitude 0x04/0x01>0x01/0x01"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("pitch_deg=-12.5"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("stopped by SIGTERM"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("good frames 0,"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace k40t::test
