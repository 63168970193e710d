// serial:///dev/ttyUSB0?baud=115200 — a terminal device in raw 8N1, no flow control, held
// exclusively (device_lock.h) from connect() to disconnect().
#include <fcntl.h>
#include <linux/serial.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <iterator>
#include <string>

#include "k40t_driver/transport/device_lock.h"
#include "links.h"

namespace k40t::transport {
namespace {

constexpr unsigned kDefaultBaud = 115200;  // the pod's rate (protocol document, 2.2)

struct BaudRate {
  unsigned value;
  speed_t code;
};

// The rates termios names with a B* constant on Linux.
constexpr BaudRate kBaudRates[] = {
    {50, B50},           {75, B75},           {110, B110},         {134, B134},
    {150, B150},         {200, B200},         {300, B300},         {600, B600},
    {1200, B1200},       {1800, B1800},       {2400, B2400},       {4800, B4800},
    {9600, B9600},       {19200, B19200},     {38400, B38400},     {57600, B57600},
    {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
    {576000, B576000},   {921600, B921600},   {1000000, B1000000}, {1152000, B1152000},
    {1500000, B1500000}, {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000},
    {3500000, B3500000}, {4000000, B4000000},
};

std::string list_baud_rates() {
  std::string out;
  for (const BaudRate& rate : kBaudRates)
    out += (out.empty() ? "" : ", ") + std::to_string(rate.value);
  return out;
}

Result<BaudRate> parse_baud(const DeviceUrl& url) {
  const auto text = url.query_value("baud");
  if (!text) return BaudRate{kDefaultBaud, B115200};
  const bool digits =
      !text->empty() && text->size() <= 8 && std::all_of(text->begin(), text->end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
      });
  if (digits) {
    const auto value = static_cast<unsigned>(std::stoul(*text));
    const auto* found = std::find_if(std::begin(kBaudRates), std::end(kBaudRates),
                                     [value](const BaudRate& rate) { return rate.value == value; });
    if (found != std::end(kBaudRates)) return *found;
  }
  return Result<BaudRate>::fail(url_error(
      url.text, "baud '" + *text + "' is not a standard rate (one of " + list_baud_rates() + ")"));
}

class SerialLink : public LinkDriver {
 public:
  SerialLink(std::string path, BaudRate baud) : path_(std::move(path)), baud_(baud) {}

  Result<int> connect(const Waiter& /*waiter*/) override {
    busy_ = false;
    UniqueFd fd;
    DeviceLock lock;  // after fd: on a failure below it is released before the fd closes
    if (Status s = lock.claim_name(path_); !s) return refused(lock, s);
    fd.reset(::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
    if (!fd.valid()) return Result<int>::fail("cannot open " + path_ + ": " + errno_text(errno));
    if (!::isatty(fd.get())) return Result<int>::fail(path_ + " is not a terminal device");
    if (Status s = lock.claim_fd(fd.get()); !s) return refused(lock, s);
    if (Status s = configure(fd.get()); !s) return Result<int>::fail(s.message());
    set_low_latency(fd.get());
    ::tcflush(fd.get(), TCIOFLUSH);  // bytes queued before we attached are stale
    lock_ = std::move(lock);
    fd_ = std::move(fd);
    return fd_.get();
  }

  void disconnect() override {
    lock_.release();  // before the close: TIOCNXCL needs the fd
    fd_.reset();
  }

  bool busy() const override { return busy_; }

  double seconds_per_byte() const override { return 10.0 / baud_.value; }  // start + 8 + stop

 private:
  Status configure(int fd) const {
    termios tio{};
    if (::tcgetattr(fd, &tio) < 0) {
      return Status::fail("cannot read the settings of " + path_ + ": " + errno_text(errno));
    }
    ::cfmakeraw(&tio);
    tio.c_cflag &= ~static_cast<tcflag_t>(CSIZE | CSTOPB | PARENB | CRTSCTS);
    tio.c_cflag |= CS8 | CLOCAL | CREAD;
    tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
    tio.c_cc[VMIN] = 1;
    tio.c_cc[VTIME] = 0;
    if (::cfsetispeed(&tio, baud_.code) < 0 || ::cfsetospeed(&tio, baud_.code) < 0 ||
        ::tcsetattr(fd, TCSANOW, &tio) < 0) {
      return Status::fail("cannot set " + path_ + " to 8N1 at " + std::to_string(baud_.value) +
                          " baud: " + errno_text(errno));
    }
    return Status::ok();
  }

  // Asks the UART driver to push received bytes up at once instead of after its latency timer
  // (16 ms on FTDI adapters). Best effort: ptys and many USB adapters answer ENOTTY or EINVAL, and
  // the link works without it.
  static void set_low_latency(int fd) {
    serial_struct serial{};
    if (::ioctl(fd, TIOCGSERIAL, &serial) < 0) return;
    serial.flags |= ASYNC_LOW_LATENCY;
    ::ioctl(fd, TIOCSSERIAL, &serial);
  }

  Result<int> refused(const DeviceLock& lock, const Status& why) {
    busy_ = lock.refusal() == DeviceLock::Refusal::kBusy;
    return Result<int>::fail(why.message());
  }

  const std::string path_;
  const BaudRate baud_;
  UniqueFd fd_;
  DeviceLock lock_;  // declared after fd_: destroyed (released) before the fd closes
  bool busy_ = false;
};

}  // namespace

LinkResult make_serial_link(const DeviceUrl& url) {
  auto baud = parse_baud(url);
  if (!baud) return LinkResult::fail(baud.error());
  return LinkResult(std::make_unique<SerialLink>(url.path, *baud));
}

}  // namespace k40t::transport
