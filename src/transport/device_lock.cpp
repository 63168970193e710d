#include "k40t_driver/transport/device_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <utility>

#include "k40t_driver/transport/unique_fd.h"

namespace k40t::transport {
namespace {

// A lock file is taken over at most this often in one claim: a stale one, then one that a
// racing opener created and dropped again.
constexpr int kClaimAttempts = 3;

// The lock files this process holds. A lock file naming our own PID that is not among them was
// left by an earlier process that had the same PID (a container restarted after a power cut
// gives its driver the same small PID again): stale like any other.
std::mutex g_held_mutex;
std::set<std::string>& held_lock_files() {
  static std::set<std::string> held;
  return held;
}
bool held_here(const std::string& path) {
  std::lock_guard<std::mutex> lock(g_held_mutex);
  return held_lock_files().count(path) != 0;
}
void set_held(const std::string& path, bool held) {
  std::lock_guard<std::mutex> lock(g_held_mutex);
  if (held) {
    held_lock_files().insert(path);
  } else {
    held_lock_files().erase(path);
  }
}

bool is_directory(const char* path) {
  struct stat info {};
  return ::stat(path, &info) == 0 && S_ISDIR(info.st_mode);
}

// The PID in a lock file: ten ASCII characters (leading blanks) and a newline, the HDB form.
// -1 when the file holds something else (e.g. the binary form of old UUCP; treated as stale).
long read_lock_pid(const std::string& path) {
  std::ifstream file(path);
  long pid = -1;
  if (!(file >> pid) || pid <= 0) return -1;
  return pid;
}

bool process_alive(long pid) {
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

// The pid holding an flock() on the file behind `fd`, from /proc/locks ("1: FLOCK ADVISORY WRITE
// 1234 00:19:5 0 EOF", device as hex major:minor, inode decimal); -1 when not listed.
long flock_holder(int fd) {
  struct stat info {};
  if (::fstat(fd, &info) < 0) return -1;
  char wanted[64];
  std::snprintf(wanted, sizeof wanted, "%02x:%02x:%llu", major(info.st_dev), minor(info.st_dev),
                static_cast<unsigned long long>(info.st_ino));
  std::ifstream locks("/proc/locks");
  std::string line;
  while (std::getline(locks, line)) {
    std::istringstream fields(line);
    std::string number, kind, mode, access, id;
    long pid = -1;
    if (!(fields >> number >> kind) || kind != "FLOCK") continue;
    if (fields >> mode >> access >> pid >> id && id == wanted && pid != ::getpid()) return pid;
  }
  return -1;
}

}  // namespace

std::string lock_file_name(const std::string& resolved_device) {
  const std::string dev = "/dev/";
  std::string name;
  if (resolved_device.compare(0, dev.size(), dev) == 0) {
    name = resolved_device.substr(dev.size());
    for (char& c : name) c = c == '/' ? '_' : c;
  } else {
    const size_t slash = resolved_device.rfind('/');
    name = slash == std::string::npos ? resolved_device : resolved_device.substr(slash + 1);
  }
  return "LCK.." + name;
}

std::string lock_directory() {
  if (const char* chosen = std::getenv("K40T_LOCK_DIR"); chosen != nullptr && *chosen != '\0')
    return chosen;
  return is_directory("/run/lock") ? "/run/lock" : "/var/lock";
}

std::string describe_process(long pid) {
  std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
  std::string name;
  std::getline(comm, name);
  const std::string text = "pid " + std::to_string(pid);
  return name.empty() ? text : text + " (" + name + ")";
}

DeviceLock::DeviceLock(DeviceLock&& other) noexcept {
  *this = std::move(other);
}

DeviceLock& DeviceLock::operator=(DeviceLock&& other) noexcept {
  if (this == &other) return *this;
  release();
  device_ = std::move(other.device_);
  lock_file_ = std::exchange(other.lock_file_, std::string());
  fd_ = std::exchange(other.fd_, -1);
  refusal_ = other.refusal_;
  return *this;
}

Status DeviceLock::refuse(Refusal why, std::string message) {
  refusal_ = why;
  return Status::fail(std::move(message));
}

Status DeviceLock::claim_name(const std::string& device) {
  release();
  device_ = device;
  refusal_ = Refusal::kNone;
  char resolved[PATH_MAX];
  if (::realpath(device.c_str(), resolved) == nullptr)
    return refuse(Refusal::kError, "cannot open " + device + ": " + errno_text(errno));
  const std::string directory = lock_directory();
  const std::string path = directory + "/" + lock_file_name(resolved);
  // Written whole under a private name, then linked: nobody ever reads a half-written lock.
  const std::string temporary = path + "." + std::to_string(::getpid()) + ".new";
  {
    UniqueFd file(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (!file.valid()) {
      // No writable lock directory (an unprivileged user on a system without the uucp group's
      // rights): flock() and TIOCEXCL still protect the device.
      return Status::ok();
    }
    char pid_text[16];
    const int size = std::snprintf(pid_text, sizeof pid_text, "%10ld\n", long{::getpid()});
    if (::write(file.get(), pid_text, static_cast<size_t>(size)) != size) {
      ::unlink(temporary.c_str());
      return Status::ok();
    }
  }
  Status outcome = Status::ok();
  for (int attempt = 0; attempt < kClaimAttempts; ++attempt) {
    if (::link(temporary.c_str(), path.c_str()) == 0) {
      lock_file_ = path;
      set_held(path, true);
      break;
    }
    if (errno != EEXIST) break;  // a lock directory we cannot link in: as above
    const long holder = read_lock_pid(path);
    if (holder == ::getpid() && held_here(path)) {
      outcome = refuse(Refusal::kBusy,
                       device + " is already open in this process (lock file " + path + ")");
      break;
    }
    if (holder > 0 && holder != ::getpid() && process_alive(holder)) {
      outcome = refuse(Refusal::kBusy, device + " is in use by " + describe_process(holder) +
                                           " (lock file " + path + ")");
      break;
    }
    ::unlink(path.c_str());  // stale: its process is gone
  }
  ::unlink(temporary.c_str());
  return outcome;
}

Status DeviceLock::claim_fd(int fd) {
  if (::flock(fd, LOCK_EX | LOCK_NB) < 0) {
    const int error = errno;
    if (error != EWOULDBLOCK)
      return refuse(Refusal::kError, "cannot lock " + device_ + ": " + errno_text(error));
    const long holder = flock_holder(fd);
    return refuse(Refusal::kBusy,
                  device_ + " is in use by " +
                      (holder > 0 ? describe_process(holder) : std::string("another program")) +
                      " (it holds an flock on the device)");
  }
  // Best effort: a device that is not a tty has no exclusive mode, and flock() already holds.
  if (::ioctl(fd, TIOCEXCL) == 0) fd_ = fd;
  return Status::ok();
}

void DeviceLock::release() {
  if (fd_ >= 0) ::ioctl(fd_, TIOCNXCL);
  fd_ = -1;
  if (lock_file_.empty()) return;
  // Removed only while it still names us (a claim that found it stale may have replaced it).
  if (read_lock_pid(lock_file_) == ::getpid()) ::unlink(lock_file_.c_str());
  set_held(lock_file_, false);
  lock_file_.clear();
}

}  // namespace k40t::transport
