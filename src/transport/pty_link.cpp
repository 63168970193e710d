// pty:///tmp/k40t_pod — the simulator's end of a pseudo-terminal. The master is ours; a symlink at
// the path points to the slave, which the driver opens as serial:///tmp/k40t_pod.
#include <fcntl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <string>

#include "links.h"

namespace k40t::transport {
namespace {

// The path may hold nothing or a symlink (ours from a previous run, now stale); anything else is
// somebody's file and is never replaced.
Status check_path_is_replaceable(const std::string& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) < 0) {
    if (errno == ENOENT) return Status::ok();
    return Status::fail("cannot inspect " + path + ": " + errno_text(errno));
  }
  if (S_ISLNK(info.st_mode)) return Status::ok();
  return Status::fail("refusing to replace " + path + ": it exists and is not a symbolic link");
}

Status make_raw(int fd, const std::string& name) {
  termios tio{};
  if (::tcgetattr(fd, &tio) < 0)
    return Status::fail("tcgetattr " + name + ": " + errno_text(errno));
  ::cfmakeraw(&tio);
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
  if (::tcsetattr(fd, TCSANOW, &tio) < 0) {
    return Status::fail("tcsetattr " + name + ": " + errno_text(errno));
  }
  return Status::ok();
}

class PtyLink : public LinkDriver {
 public:
  explicit PtyLink(std::string path) : path_(std::move(path)) {}

  Status preflight() override { return check_path_is_replaceable(path_); }

  Result<int> connect(const Waiter& /*waiter*/) override {
    if (Status s = create_pair(); !s) {
      release();
      return Result<int>::fail(s.message());
    }
    if (Status s = publish_symlink(); !s) {
      release();
      return Result<int>::fail(s.message());
    }
    return master_.get();
  }

  void disconnect() override {
    remove_symlink_if_ours();
    release();
  }

  // Nobody has drained the slave for a while (no client attached, or it is stuck): drop its
  // stale input so the simulator keeps running, as a serial line without a listener would.
  bool relieve_stalled_write() override { return ::tcflush(slave_.get(), TCIFLUSH) == 0; }

 private:
  Status create_pair() {
    master_.reset(::posix_openpt(O_RDWR | O_NOCTTY));
    if (!master_.valid()) return Status::fail("posix_openpt: " + errno_text(errno));
    char name[PATH_MAX] = {};
    if (::grantpt(master_.get()) < 0 || ::unlockpt(master_.get()) < 0 ||
        ::ptsname_r(master_.get(), name, sizeof name) != 0) {
      return Status::fail("cannot unlock a pseudo-terminal: " + errno_text(errno));
    }
    slave_name_ = name;
    if (Status s = make_nonblocking(master_.get()); !s) return s;
    // Holding the slave open ourselves keeps the master from reporting POLLHUP (and failing
    // reads with EIO) whenever no client has it open.
    slave_.reset(::open(name, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
    if (!slave_.valid())
      return Status::fail("cannot open " + slave_name_ + ": " + errno_text(errno));
    return make_raw(slave_.get(), slave_name_);
  }

  // Atomically points path_ at the slave: a client polling the path never sees it missing.
  Status publish_symlink() {
    if (Status s = check_path_is_replaceable(path_); !s) return s;
    const std::string temporary = path_ + ".new";
    ::unlink(temporary.c_str());
    if (::symlink(slave_name_.c_str(), temporary.c_str()) < 0) {
      return Status::fail("cannot create the symlink " + temporary + ": " + errno_text(errno));
    }
    if (::rename(temporary.c_str(), path_.c_str()) < 0) {
      const int error = errno;
      ::unlink(temporary.c_str());
      return Status::fail("cannot create the symlink " + path_ + ": " + errno_text(error));
    }
    published_ = true;
    return Status::ok();
  }

  void remove_symlink_if_ours() {
    if (!published_) return;
    published_ = false;
    char target[PATH_MAX] = {};
    const ssize_t n = ::readlink(path_.c_str(), target, sizeof target - 1);
    if (n > 0 && std::string(target, static_cast<size_t>(n)) == slave_name_)
      ::unlink(path_.c_str());
  }

  void release() {
    slave_.reset();
    master_.reset();
  }

  const std::string path_;
  UniqueFd master_;
  UniqueFd slave_;
  std::string slave_name_;
  bool published_ = false;
};

}  // namespace

LinkResult make_pty_link(const DeviceUrl& url) {
  return LinkResult(std::make_unique<PtyLink>(url.path));
}

}  // namespace k40t::transport
