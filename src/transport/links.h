// One factory per URL scheme; the scheme table in transport.cpp maps names to these. Each checks
// the scheme's own options (baud, bind address) and fails with a message naming the URL.
#pragma once

#include <memory>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/transport/device_url.h"
#include "k40t_driver/transport/link_driver.h"

namespace k40t::transport {

using LinkResult = Result<std::unique_ptr<LinkDriver>>;

LinkResult make_serial_link(const DeviceUrl& url);      // serial:///dev/ttyUSB0?baud=115200
LinkResult make_pty_link(const DeviceUrl& url);         // pty:///tmp/k40t_pod
LinkResult make_udp_client_link(const DeviceUrl& url);  // udp://host:port[?bind=addr:port]
LinkResult make_udp_server_link(const DeviceUrl& url);  // udp-server://addr:port
LinkResult make_tcp_client_link(const DeviceUrl& url);  // tcp://host:port
LinkResult make_tcp_server_link(const DeviceUrl& url);  // tcp-server://addr:port

}  // namespace k40t::transport
