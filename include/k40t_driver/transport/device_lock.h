// Exclusive use of a serial device (a USB adapter, or the simulator's pseudo-terminal), the way
// other serial programs (minicom, picocom, screen, gpsd, ...) expect it:
//   1. the UUCP/HDB lock file /run/lock/LCK..<name> (or /var/lock when /run/lock is missing),
//      holding the owner's PID as ten ASCII characters and a newline; a lock whose process is gone
//      (killed, power cut) is stale and taken over;
//   2. flock(LOCK_EX) on the open device: the same device reached through another path (a
//      symlink) or by a program that skips lock files;
//   3. TIOCEXCL: the kernel refuses every further open() of the tty (EBUSY), except root's.
// A second opener is refused at once with a message naming the holder: its pid and program name
// from /proc ("/dev/ttyUSB0 is in use by pid 1234 (minicom)"). Everything is given back by
// release() or the destructor, i.e. on every path that closes the device.
#pragma once

#include <string>

#include "k40t_driver/codec/result.h"

namespace k40t::transport {

// The lock file's name for a device path (symlinks resolved): "LCK..ttyUSB0" for /dev/ttyUSB0,
// "LCK..pts_3" for /dev/pts/3 (the path below /dev, '/' as '_'); other paths: their file name.
std::string lock_file_name(const std::string& resolved_device);

// The directory lock files go to: $K40T_LOCK_DIR if set, else /run/lock, else /var/lock.
std::string lock_directory();

// "pid 1234 (minicom)"; "pid 1234" when /proc does not name it.
std::string describe_process(long pid);

class DeviceLock {
 public:
  // Why a claim failed.
  enum class Refusal {
    kNone,
    kBusy,   // another process (named in the message) holds the device
    kError,  // the lock could not be checked (e.g. unreadable device path)
  };

  DeviceLock() = default;
  DeviceLock(DeviceLock&& other) noexcept;
  DeviceLock& operator=(DeviceLock&& other) noexcept;
  DeviceLock(const DeviceLock&) = delete;
  DeviceLock& operator=(const DeviceLock&) = delete;
  ~DeviceLock() { release(); }

  // Step 1, before the device is opened (opening a tty may toggle its modem lines). `device` is
  // the path as configured.
  Status claim_name(const std::string& device);
  // Steps 2 and 3 on the freshly opened device.
  Status claim_fd(int fd);
  // Gives everything back; call before closing the fd (TIOCEXCL outlives our fd on a tty others
  // still hold open, like the simulator's pty). Idempotent.
  void release();

  // Of the last failed claim.
  Refusal refusal() const { return refusal_; }
  const std::string& lock_file() const { return lock_file_; }

 private:
  Status refuse(Refusal why, std::string message);

  std::string device_;     // as configured, for messages
  std::string lock_file_;  // ours while non-empty
  int fd_ = -1;            // TIOCEXCL set on it while >= 0
  Refusal refusal_ = Refusal::kNone;
};

}  // namespace k40t::transport
