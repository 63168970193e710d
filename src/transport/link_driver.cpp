#include "k40t_driver/transport/link_driver.h"

#include <unistd.h>

namespace k40t::transport {

ssize_t LinkDriver::receive(int fd, uint8_t* buffer, size_t size) {
  return ::read(fd, buffer, size);
}

ssize_t LinkDriver::transmit(int fd, const uint8_t* data, size_t size) {
  return ::write(fd, data, size);
}

}  // namespace k40t::transport
