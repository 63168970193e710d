// pty:// (simulator side) against serial:// on its symlink (driver side): round trips, the
// simulator's disconnect fault, a device that appears late, symlink rules, stats, close().
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "transport_test_support.h"

namespace k40t::transport {
namespace {

using testing::Endpoint;
using ::testing::HasSubstr;
using testing::random_bytes;
using testing::ScratchDir;

// Bigger than one read (the tty layer hands over at most 4 KiB at a time) and than the pty's
// buffers, so both the reader's loop and the writer's "wait for room" path run.
constexpr size_t kLargePayload = 200 * 1024;

bool is_symlink(const std::string& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0 && S_ISLNK(info.st_mode);
}

class PtyPair : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(pod.transport->open()) << "pty open";
    ASSERT_TRUE(pod.log.wait_for(LinkState::kConnected)) << pod.transport->stats().last_error;
    ASSERT_TRUE(driver.transport->open()) << "serial open";
    ASSERT_TRUE(driver.log.wait_for(LinkState::kConnected)) << driver.transport->stats().last_error;
  }

  // Sends from one side, checks the other receives exactly those bytes.
  static void expect_delivered(Endpoint& from, Endpoint& to, const std::vector<uint8_t>& bytes) {
    const size_t before = to.received.size();
    const Status sent = from.send(bytes);
    ASSERT_TRUE(sent) << sent.message();
    ASSERT_TRUE(to.received.wait_for_size(before + bytes.size()))
        << "got " << to.received.size() - before << " of " << bytes.size();
    const auto all = to.received.bytes();
    EXPECT_EQ(std::vector<uint8_t>(all.begin() + static_cast<long>(before), all.end()), bytes);
  }

  ScratchDir dir;
  const std::string path = dir.file("pod");
  Endpoint pod{"pty://" + path};
  Endpoint driver{"serial://" + path + "?baud=115200"};
};

TEST_F(PtyPair, PtyPublishesASymlinkToItsSlave) {
  ASSERT_TRUE(is_symlink(path));
  EXPECT_THAT(std::filesystem::read_symlink(path).string(), HasSubstr("/dev/pts/"));
}

TEST_F(PtyPair, SmallMessagesBothWays) {
  expect_delivered(pod, driver, {0xFD, 0x01, 0x02, 0x03});
  expect_delivered(driver, pod, {0xFD, 0x04, 0x05});
}

TEST_F(PtyPair, LargePayloadFromPodToDriver) {
  expect_delivered(pod, driver, random_bytes(kLargePayload, 1));
  EXPECT_GT(driver.received.callbacks(), 1u) << "expected the payload to arrive in several reads";
}

TEST_F(PtyPair, LargePayloadFromDriverToPod) {
  expect_delivered(driver, pod, random_bytes(kLargePayload, 2));
  EXPECT_GT(pod.received.callbacks(), 1u) << "expected the payload to arrive in several reads";
}

TEST_F(PtyPair, StatsCountBytesReadsWritesAndConnects) {
  const auto first = random_bytes(100, 3);
  const auto second = random_bytes(250, 4);
  expect_delivered(driver, pod, first);
  expect_delivered(driver, pod, second);
  const LinkStats sent = driver.transport->stats();
  EXPECT_EQ(sent.writes, 2u);
  EXPECT_EQ(sent.bytes_sent, 350u);
  EXPECT_EQ(sent.connects, 1u);
  EXPECT_EQ(sent.disconnects, 0u);
  EXPECT_EQ(sent.send_errors, 0u);
  const LinkStats received = pod.transport->stats();
  EXPECT_EQ(received.bytes_received, 350u);
  EXPECT_EQ(received.reads, pod.received.callbacks());
  EXPECT_EQ(received.writes, 0u);
}

TEST_F(PtyPair, DriverReconnectsAfterThePodClosesAndReopens) {
  pod.transport->close();
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(path)))
      << "close() must remove the symlink";
  ASSERT_TRUE(driver.log.wait_for(LinkState::kReconnecting));
  EXPECT_THAT(driver.transport->stats().last_error, HasSubstr(path));
  EXPECT_EQ(driver.transport->stats().disconnects, 1u);

  ASSERT_TRUE(pod.transport->open());
  ASSERT_TRUE(driver.log.wait_for(LinkState::kConnected, 2))
      << driver.transport->stats().last_error;
  EXPECT_EQ(driver.transport->stats().connects, 2u);
  expect_delivered(pod, driver, {0x10, 0x20, 0x30});
  expect_delivered(driver, pod, {0x40, 0x50});
  EXPECT_EQ(pod.log.states(), (std::vector<LinkState>{LinkState::kConnecting, LinkState::kConnected,
                                                      LinkState::kClosed, LinkState::kConnecting,
                                                      LinkState::kConnected}));
}

TEST_F(PtyPair, SendWhileReconnectingFailsNamingTheDevice) {
  pod.transport->close();
  ASSERT_TRUE(driver.log.wait_for(LinkState::kReconnecting));
  const std::vector<uint8_t> bytes = {1, 2, 3};
  const Status sent = driver.send(bytes);
  ASSERT_FALSE(sent);
  EXPECT_THAT(sent.message(), HasSubstr(path));
  EXPECT_THAT(sent.message(), HasSubstr("not connected"));
  EXPECT_EQ(driver.transport->stats().send_errors, 1u);
}

TEST_F(PtyPair, PodWritesWithoutAReaderDoNotBlockForever) {
  driver.transport->close();
  // Far more than the pty buffers hold: the pty drops the stale input nobody reads.
  const auto chunk = random_bytes(16 * 1024, 5);
  for (int i = 0; i < 8; ++i) {
    const Status sent = pod.send(chunk);
    ASSERT_TRUE(sent) << "chunk " << i << ": " << sent.message();
  }
}

TEST_F(PtyPair, CloseTwiceAndSendAfterClose) {
  driver.transport->close();
  driver.transport->close();
  EXPECT_EQ(driver.transport->state(), LinkState::kClosed);
  EXPECT_EQ(driver.log.states().back(), LinkState::kClosed);
  EXPECT_EQ(driver.log.count(LinkState::kClosed), 1u);
  const Status sent = driver.send({1});
  ASSERT_FALSE(sent);
  EXPECT_THAT(sent.message(), HasSubstr("serial://" + path));
  pod.transport->close();
  pod.transport->close();
  EXPECT_EQ(pod.transport->state(), LinkState::kClosed);
}

TEST(PtyTransport, AbsentSerialDeviceIsRetriedUntilThePtyAppears) {
  ScratchDir dir;
  const std::string path = dir.file("late_pod");
  Endpoint driver("serial://" + path);
  ASSERT_TRUE(driver.transport->open()) << "a missing device must not fail open()";
  ASSERT_TRUE(driver.log.wait_for(LinkState::kReconnecting));
  const std::string error = driver.transport->stats().last_error;
  EXPECT_THAT(error, HasSubstr(path));
  EXPECT_THAT(error, HasSubstr("No such file or directory"));
  EXPECT_THAT(driver.log.last_reason(LinkState::kReconnecting), HasSubstr(path));

  Endpoint pod("pty://" + path);
  ASSERT_TRUE(pod.transport->open());
  ASSERT_TRUE(driver.log.wait_for(LinkState::kConnected)) << driver.transport->stats().last_error;
  const std::vector<uint8_t> hello = {0xFD, 0xAA};
  ASSERT_TRUE(pod.send(hello));
  ASSERT_TRUE(driver.received.wait_for_size(hello.size()));
  EXPECT_EQ(driver.received.bytes(), hello);
}

TEST(PtyTransport, ReplacesAStaleSymlinkAndRemovesItOnClose) {
  ScratchDir dir;
  const std::string path = dir.file("pod");
  ASSERT_EQ(::symlink("/dev/pts/does-not-exist", path.c_str()), 0);
  Endpoint pod("pty://" + path);
  ASSERT_TRUE(pod.transport->open());
  ASSERT_TRUE(pod.log.wait_for(LinkState::kConnected)) << pod.transport->stats().last_error;
  EXPECT_NE(std::filesystem::read_symlink(path).string(), "/dev/pts/does-not-exist");
  pod.transport->close();
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(path)));
}

TEST(PtyTransport, RefusesToOverwriteARegularFile) {
  ScratchDir dir;
  const std::string path = dir.file("precious.txt");
  std::ofstream(path) << "keep me";
  Endpoint pod("pty://" + path);
  const Status opened = pod.transport->open();
  ASSERT_FALSE(opened);
  EXPECT_THAT(opened.message(), HasSubstr(path));
  EXPECT_THAT(opened.message(), HasSubstr("not a symbolic link"));
  std::ifstream kept(path);
  std::string content;
  std::getline(kept, content);
  EXPECT_EQ(content, "keep me");
}

TEST(PtyTransport, SerialOnARegularFileIsNotATerminal) {
  ScratchDir dir;
  const std::string path = dir.file("plain");
  std::ofstream(path) << "x";
  Endpoint driver("serial://" + path);
  ASSERT_TRUE(driver.transport->open());
  ASSERT_TRUE(driver.log.wait_for(LinkState::kReconnecting));
  EXPECT_THAT(driver.transport->stats().last_error, HasSubstr(path + " is not a terminal"));
}

TEST(PtyTransport, CloseWithoutOpenAndOpenTwice) {
  ScratchDir dir;
  Endpoint pod("pty://" + dir.file("pod"));
  pod.transport->close();  // never opened: nothing to do
  EXPECT_EQ(pod.log.states().size(), 0u);
  ASSERT_TRUE(pod.transport->open());
  const Status again = pod.transport->open();
  ASSERT_FALSE(again);
  EXPECT_THAT(again.message(), HasSubstr("already open"));
}

TEST(PtyTransport, CloseFromInsideACallbackDoesNotDeadlock) {
  ScratchDir dir;
  const std::string path = dir.file("pod");
  Endpoint pod("pty://" + path);
  testing::ByteSink got;
  auto made = make_transport("serial://" + path);
  ASSERT_TRUE(made);
  Transport& driver = **made;
  driver.set_receive_callback([&](const uint8_t* data, size_t size) {
    got.callback()(data, size);
    driver.close();  // from the I/O thread: only asks it to stop
  });
  ASSERT_TRUE(pod.transport->open());
  ASSERT_TRUE(pod.log.wait_for(LinkState::kConnected));
  ASSERT_TRUE(driver.open());
  ASSERT_TRUE(testing::eventually([&] { return driver.state() == LinkState::kConnected; }));
  ASSERT_TRUE(pod.send({7}));
  ASSERT_TRUE(testing::eventually([&] { return driver.state() == LinkState::kClosed; }));
  EXPECT_EQ(got.size(), 1u);
  ASSERT_TRUE(driver.open()) << "reopen after a close() from a callback";
  ASSERT_TRUE(testing::eventually([&] { return driver.state() == LinkState::kConnected; }));
}

}  // namespace
}  // namespace k40t::transport
