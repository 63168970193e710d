// The link's state as the user reads it (driver/link_monitor.h): waiting until the first valid
// frame, "cannot open" apart from "lost", "no answer" after link_timeout (a UDP socket to nobody),
// and a stop that is never a loss. Then the same through PodDriver with a real UDP socket.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <mutex>
#include <thread>
#include <vector>

#include "eventually.h"
#include "k40t_driver/driver/link_monitor.h"
#include "k40t_driver/driver/pod_driver.h"
#include "transport_test_support.h"

namespace k40t::driver {
namespace {

using ::testing::HasSubstr;
using transport::LinkState;
using Clock = LinkMonitor::Clock;
using namespace std::chrono_literals;

constexpr const char* kUrl = "udp://127.0.0.1:9";

// The states a sequence of events produced, in order.
class Recorder {
 public:
  void take(const std::optional<PodLinkReport>& report) {
    if (report) reports.push_back(*report);
  }
  std::vector<PodLink> states() const {
    std::vector<PodLink> out;
    for (const auto& r : reports) out.push_back(r.state);
    return out;
  }
  std::vector<PodLinkReport> reports;
};

TEST(LinkMonitor, WaitsForTheFirstFrameBeforeSayingConnected) {
  LinkMonitor monitor(kUrl, 3.0);
  Recorder seen;
  const Clock::time_point t0 = Clock::now();
  seen.take(monitor.on_transport(LinkState::kConnecting, "connecting", t0));
  seen.take(monitor.on_transport(LinkState::kConnected, "connected to " + std::string(kUrl), t0));
  ASSERT_EQ(seen.states(), std::vector<PodLink>{PodLink::kWaiting});
  EXPECT_EQ(seen.reports[0].text, "waiting for the pod at udp://127.0.0.1:9");
  seen.take(monitor.on_frame(t0 + 100ms));
  seen.take(monitor.on_frame(t0 + 200ms));  // no change, no report
  ASSERT_EQ(seen.states(), (std::vector<PodLink>{PodLink::kWaiting, PodLink::kConnected}));
  EXPECT_EQ(seen.reports[1].text, "connected to the pod at udp://127.0.0.1:9");
}

TEST(LinkMonitor, NothingAnsweringForTheTimeoutIsSaidOnce) {
  LinkMonitor monitor(kUrl, 3.0);
  Recorder seen;
  const Clock::time_point t0 = Clock::now();
  seen.take(monitor.on_transport(LinkState::kConnected, "", t0));
  ASSERT_TRUE(monitor.deadline());
  EXPECT_EQ(*monitor.deadline(), t0 + 3s);
  seen.take(monitor.on_tick(t0 + 2900ms));  // not yet
  seen.take(monitor.on_tick(t0 + 3s));
  seen.take(monitor.on_tick(t0 + 10s));  // said once
  ASSERT_EQ(seen.states(), (std::vector<PodLink>{PodLink::kWaiting, PodLink::kNoAnswer}));
  EXPECT_EQ(seen.reports[1].text,
            "waiting for the pod at udp://127.0.0.1:9: nothing has answered for 3.0 s");
  EXPECT_FALSE(monitor.deadline());
  // The pod speaks: connected; then it falls silent: no answer, in other words.
  seen.take(monitor.on_frame(t0 + 11s));
  seen.take(monitor.on_tick(t0 + 14500ms));
  ASSERT_EQ(seen.reports.size(), 4u);
  EXPECT_EQ(seen.reports[2].state, PodLink::kConnected);
  EXPECT_EQ(seen.reports[3].text, "no answer from the pod at udp://127.0.0.1:9 for 3.5 s");
}

TEST(LinkMonitor, ADeviceThatNeverOpenedIsCannotOpenNotLost) {
  LinkMonitor monitor("serial:///dev/ttyNONE?baud=115200", 3.0);
  Recorder seen;
  seen.take(monitor.on_transport(
      LinkState::kReconnecting,
      "serial:///dev/ttyNONE?baud=115200: cannot open /dev/ttyNONE: No such file or directory "
      "(errno 2)",
      Clock::now()));
  ASSERT_EQ(seen.states(), std::vector<PodLink>{PodLink::kCannotOpen});
  EXPECT_EQ(seen.reports[0].text,
            "cannot open serial:///dev/ttyNONE?baud=115200: No such file or directory (errno 2) "
            "(retrying)");
  EXPECT_FALSE(monitor.deadline());  // no "no answer" on top of it
}

TEST(LinkMonitor, AnEstablishedLinkThatDropsIsLostThenWaitingAgain) {
  LinkMonitor monitor(kUrl, 3.0);
  Recorder seen;
  const Clock::time_point t0 = Clock::now();
  monitor.on_transport(LinkState::kConnected, "", t0);
  monitor.on_frame(t0);
  seen.take(monitor.on_transport(LinkState::kReconnecting, std::string(kUrl) + ": hang-up", t0));
  seen.take(monitor.on_transport(LinkState::kConnected, "", t0 + 1s));
  ASSERT_EQ(seen.states(), (std::vector<PodLink>{PodLink::kLost, PodLink::kWaiting}));
  EXPECT_EQ(seen.reports[0].text,
            "link to the pod at udp://127.0.0.1:9 lost: hang-up; reconnecting");
}

TEST(LinkMonitor, AStopIsNeverALoss) {
  LinkMonitor monitor(kUrl, 3.0);
  Recorder seen;
  const Clock::time_point t0 = Clock::now();
  monitor.on_transport(LinkState::kConnected, "", t0);
  monitor.on_frame(t0);
  seen.take(monitor.on_stop());
  // What the transport says while it closes changes nothing any more.
  seen.take(monitor.on_transport(LinkState::kReconnecting, "hang-up", t0));
  seen.take(monitor.on_transport(LinkState::kClosed, "closed", t0));
  seen.take(monitor.on_tick(t0 + 1h));
  ASSERT_EQ(seen.states(), std::vector<PodLink>{PodLink::kStopped});
  EXPECT_EQ(seen.reports[0].text, "link to the pod at udp://127.0.0.1:9 closed");
}

// Through the driver: a UDP socket to a port nobody listens on "connects" at once; the driver
// still says it is waiting, then that nothing answers; a loss during a requested shutdown is
// reported as the stop.
class DriverLinkReports : public ::testing::Test {
 protected:
  std::unique_ptr<PodDriver> make(const std::string& device, double link_timeout_s,
                                  std::function<bool()> shutting_down = {}) {
    DriverOptions o;
    o.device = device;
    o.link_timeout_s = link_timeout_s;
    o.time_sync_period_s = 0;
    o.laser_target_period_s = 0;
    auto created = PodDriver::create(o, [] { return StampNs{0}; });
    EXPECT_TRUE(created) << created.error();
    auto driver = std::move(created).value();
    driver->on_link_report([this](const PodLinkReport& r) {
      std::lock_guard<std::mutex> lock(mutex_);
      reports_.push_back(r);
    });
    if (shutting_down) driver->set_shutdown_query(std::move(shutting_down));
    return driver;
  }
  std::vector<PodLink> states() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<PodLink> out;
    for (const auto& r : reports_) out.push_back(r.state);
    return out;
  }
  bool seen(PodLink state) const {
    const auto all = states();
    return std::find(all.begin(), all.end(), state) != all.end();
  }

  mutable std::mutex mutex_;
  std::vector<PodLinkReport> reports_;
};

TEST_F(DriverLinkReports, AUdpLinkToNobodyWaitsThenSaysNothingAnswers) {
  transport::testing::LoopbackSocket nobody(SOCK_DGRAM);  // bound, never answers
  auto driver = make("udp://127.0.0.1:" + std::to_string(nobody.port()), 0.3);
  ASSERT_TRUE(driver->start());
  ASSERT_TRUE(test::eventually([&] { return seen(PodLink::kNoAnswer); }));
  EXPECT_FALSE(seen(PodLink::kConnected));
  EXPECT_EQ(states().front(), PodLink::kWaiting);
  EXPECT_THAT(driver->link_report().text, HasSubstr("nothing has answered for"));
  driver->stop();
  EXPECT_EQ(states().back(), PodLink::kStopped);
}

TEST_F(DriverLinkReports, ALossWhileShuttingDownIsTheStop) {
  transport::testing::ScratchDir dir;
  const std::string path = dir.file("pod");
  auto pod = std::make_unique<transport::testing::Endpoint>("pty://" + path);
  ASSERT_TRUE(pod->transport->open());
  ASSERT_TRUE(pod->log.wait_for(LinkState::kConnected));
  std::atomic<bool> shutting_down{false};
  auto driver = make("serial://" + path, 3.0, [&] { return shutting_down.load(); });
  ASSERT_TRUE(driver->start());
  ASSERT_TRUE(test::eventually([&] { return seen(PodLink::kWaiting); }));
  // Ctrl-C: the simulator, which got it too, closes the link before this process has taken
  // its signal (another thread takes it a moment later).
  std::thread late_signal([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    shutting_down = true;
  });
  pod.reset();
  late_signal.join();
  ASSERT_TRUE(test::eventually([&] { return seen(PodLink::kStopped); }));
  driver->stop();
  EXPECT_FALSE(seen(PodLink::kLost));
}

}  // namespace
}  // namespace k40t::driver
