// One reader per serial device (device_lock.h), on the simulator's pseudo-terminal: the lock
// file and its format, a holder in another process named in the refusal (lock file or flock),
// in-process double opens, stale locks taken over, everything given back on close, and the k40t
// tool refusing at once. The tests run as root, whom TIOCEXCL does not stop: the lock file and
// flock are what they can check; TIOCEXCL is checked as a flag (TIOCGEXCL).
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "k40t_driver/transport/device_lock.h"
#include "run_tool.h"
#include "transport_test_support.h"

extern char** environ;

namespace k40t::transport {
namespace {

using testing::Endpoint;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::ScratchDir;

// A child process that lives until killed (its /proc name: "sleep").
class SleepingProcess {
 public:
  SleepingProcess() {
    char* argv[] = {const_cast<char*>("sleep"), const_cast<char*>("60"), nullptr};
    if (::posix_spawn(&pid_, "/bin/sleep", nullptr, nullptr, argv, environ) != 0) pid_ = -1;
  }
  ~SleepingProcess() { stop(); }
  pid_t pid() const { return pid_; }
  void stop() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

 private:
  pid_t pid_ = -1;
};

// A forked child that opens `device` and holds an flock on it until killed.
class FlockingProcess {
 public:
  explicit FlockingProcess(const std::string& device) {
    int ready[2];
    if (::pipe(ready) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {  // only async-signal-safe calls from here
      const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
      const char ok = fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) == 0 ? '1' : '0';
      [[maybe_unused]] const ssize_t n = ::write(ready[1], &ok, 1);
      while (true) ::pause();
    }
    char ok = '0';
    if (pid_ > 0 && ::read(ready[0], &ok, 1) != 1) ok = '0';
    locked_ = ok == '1';
    ::close(ready[0]);
    ::close(ready[1]);
  }
  ~FlockingProcess() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  pid_t pid() const { return pid_; }
  bool locked() const { return locked_; }

 private:
  pid_t pid_ = -1;
  bool locked_ = false;
};

std::string resolved(const std::string& path) {
  char buffer[PATH_MAX];
  return ::realpath(path.c_str(), buffer) ? buffer : "";
}

void write_lock_file(const std::string& path, long pid) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  ASSERT_NE(file, nullptr) << path;
  std::fprintf(file, "%10ld\n", pid);
  std::fclose(file);
}

class DeviceLockTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(pod.transport->open());
    ASSERT_TRUE(pod.log.wait_for(LinkState::kConnected)) << pod.transport->stats().last_error;
    device = resolved(path);
    ASSERT_FALSE(device.empty());
    lock_file = lock_directory() + "/" + lock_file_name(device);
  }

  // The driver's side: serial:// on the simulator's symlink.
  std::unique_ptr<Endpoint> open_driver() {
    auto driver = std::make_unique<Endpoint>("serial://" + path);
    EXPECT_TRUE(driver->transport->open());
    return driver;
  }
  static bool busy(const Endpoint& e) { return e.transport->stats().device_busy; }

  ScratchDir dir;
  const std::string path = dir.file("pod");
  Endpoint pod{"pty://" + path};
  std::string device;     // /dev/pts/N
  std::string lock_file;  // /run/lock/LCK..pts_N
};

TEST(DeviceLockNames, FollowTheUucpConvention) {
  EXPECT_EQ(lock_file_name("/dev/ttyUSB0"), "LCK..ttyUSB0");
  EXPECT_EQ(lock_file_name("/dev/pts/3"), "LCK..pts_3");
  EXPECT_EQ(lock_file_name("/srv/serial/port"), "LCK..port");
  EXPECT_EQ(describe_process(::getpid()).rfind("pid " + std::to_string(::getpid()) + " (", 0), 0u);
}

TEST_F(DeviceLockTest, TheHolderWritesItsPidAsTenCharactersAndExcludesTheTty) {
  auto driver = open_driver();
  ASSERT_TRUE(driver->log.wait_for(LinkState::kConnected)) << driver->transport->stats().last_error;
  char expected[16];
  std::snprintf(expected, sizeof expected, "%10d\n", static_cast<int>(::getpid()));
  EXPECT_EQ(k40t::test::read_file(lock_file), expected);
  const int probe = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);  // root may
  ASSERT_GE(probe, 0);
  int exclusive = 0;
  ASSERT_EQ(::ioctl(probe, TIOCGEXCL, &exclusive), 0);
  EXPECT_EQ(exclusive, 1);
  // Closed: the lock file goes, the tty is shared again, the flock is free.
  driver.reset();
  EXPECT_FALSE(std::filesystem::exists(lock_file));
  ASSERT_EQ(::ioctl(probe, TIOCGEXCL, &exclusive), 0);
  EXPECT_EQ(exclusive, 0);
  EXPECT_EQ(::flock(probe, LOCK_EX | LOCK_NB), 0);
  ::close(probe);
}

TEST_F(DeviceLockTest, ALockFileOfALiveProcessRefusesAtOnceNamingItThenIsTakenOverWhenItDies) {
  SleepingProcess holder;
  ASSERT_GT(holder.pid(), 0);
  write_lock_file(lock_file, holder.pid());
  auto driver = open_driver();
  ASSERT_TRUE(testing::eventually([&] { return busy(*driver); }));
  const std::string reason = driver->log.last_reason(LinkState::kReconnecting);
  EXPECT_THAT(reason, HasSubstr("is in use by pid " + std::to_string(holder.pid()) + " (sleep)"));
  EXPECT_THAT(reason, HasSubstr(lock_file));
  EXPECT_EQ(driver->log.count(LinkState::kConnected), 0u);
  // The holder dies without cleaning up (a power cut): its lock is stale and taken over.
  holder.stop();
  ASSERT_TRUE(driver->log.wait_for(LinkState::kConnected)) << driver->transport->stats().last_error;
  EXPECT_FALSE(busy(*driver));
  char expected[16];
  std::snprintf(expected, sizeof expected, "%10d\n", static_cast<int>(::getpid()));
  EXPECT_EQ(k40t::test::read_file(lock_file), expected);
}

TEST_F(DeviceLockTest, AnFlockOfAProgramWithoutLockFilesRefusesNamingIt) {
  FlockingProcess holder(device);
  ASSERT_TRUE(holder.locked());
  auto driver = open_driver();
  ASSERT_TRUE(testing::eventually([&] { return busy(*driver); }));
  const std::string reason = driver->log.last_reason(LinkState::kReconnecting);
  EXPECT_THAT(reason, HasSubstr("is in use by pid " + std::to_string(holder.pid())));
  EXPECT_THAT(reason, HasSubstr("flock"));
  // Our lock file is not left behind by the refused attempt.
  EXPECT_FALSE(std::filesystem::exists(lock_file));
}

TEST_F(DeviceLockTest, ASecondOpenerInTheSameProcessIsRefused) {
  auto first = open_driver();
  ASSERT_TRUE(first->log.wait_for(LinkState::kConnected));
  auto second = open_driver();
  ASSERT_TRUE(testing::eventually([&] { return busy(*second); }));
  EXPECT_THAT(second->log.last_reason(LinkState::kReconnecting),
              HasSubstr("already open in this process"));
  // The first keeps its lock and its link.
  EXPECT_TRUE(std::filesystem::exists(lock_file));
  EXPECT_EQ(first->transport->state(), LinkState::kConnected);
}

TEST_F(DeviceLockTest, ALockFileWithOurPidThatWeDoNotHoldIsStale) {
  // Left by an earlier process with the same PID (a restarted container's driver).
  write_lock_file(lock_file, ::getpid());
  auto driver = open_driver();
  ASSERT_TRUE(driver->log.wait_for(LinkState::kConnected)) << driver->transport->stats().last_error;
  EXPECT_FALSE(busy(*driver));
}

TEST_F(DeviceLockTest, TheToolRefusesAHeldDeviceAtOnceWithExitCodeOne) {
  auto driver = open_driver();
  ASSERT_TRUE(driver->log.wait_for(LinkState::kConnected));
  for (const char* command : {"monitor", "send"}) {
    const std::string args = std::string(command) + " 'serial://" + path + "'" +
                             (std::string(command) == "send" ? " laser_range enable=1" : "");
    const auto start = std::chrono::steady_clock::now();
    const k40t::test::ToolRun run = k40t::test::run_k40t(args);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(run.exit_code, 1) << command << ": " << run.err;
    EXPECT_THAT(run.err, HasSubstr("is in use by pid " + std::to_string(::getpid()))) << command;
    EXPECT_THAT(run.err, Not(HasSubstr("not connected after"))) << command;
    // Not a timing assertion on our code's speed: "at once" means not after a connect timeout
    // (send's is 3 s) and not never (monitor would wait for Ctrl-C).
    EXPECT_LT(seconds, 2.5) << command;
  }
  EXPECT_EQ(driver->transport->state(), LinkState::kConnected);
}

}  // namespace
}  // namespace k40t::transport
