// k40t_sim with a --link it cannot open: start() fails naming the link and why (the program then
// exits 1, docs/simulator.md), instead of printing "serving ..." and retrying for ever.
#include <gtest/gtest.h>

#include <sys/socket.h>

#include <string>

#include "k40t_driver/sim/pod_server.h"
#include "k40t_driver/sim/sim_options.h"
#include "transport_test_support.h"

namespace k40t::sim {
namespace {

using transport::testing::LoopbackSocket;
using transport::testing::ScratchDir;

// The error PodServer::start() gives for `link` (as the host sees it), or "" if it started.
std::string start_error(const std::string& link) {
  Result<SimOptions> options = parse_sim_options({"--link", link});
  EXPECT_TRUE(options) << options.error();
  PodServer server(options.value());
  const Status started = server.start();
  server.stop();
  return started ? "" : started.message();
}

TEST(SimLinkErrors, APtyInAMissingDirectory) {
  const ScratchDir dir;
  const std::string path = dir.file("missing/pod");
  const std::string error = start_error("pty:" + path);
  EXPECT_NE(error.find("cannot open pty://" + path), std::string::npos) << error;
}

TEST(SimLinkErrors, AUdpPortInUse) {
  const LoopbackSocket taken(SOCK_DGRAM);
  ASSERT_GT(taken.port(), 0);
  const std::string link = "udp://127.0.0.1:" + std::to_string(taken.port());
  const std::string error = start_error(link);
  EXPECT_NE(error.find("cannot open udp-server://127.0.0.1:" + std::to_string(taken.port())),
            std::string::npos)
      << error;
}

TEST(SimLinkErrors, AnAddressNotOnThisMachine) {
  // 192.0.2.0/24 is TEST-NET-1 (RFC 5737): never an address of this host.
  const std::string error = start_error(
      "udp://192.0.2.1:" + std::to_string(transport::testing::free_loopback_port(SOCK_DGRAM)));
  EXPECT_NE(error.find("cannot open udp-server://192.0.2.1"), std::string::npos) << error;
}

TEST(SimLinkErrors, AGoodLinkStarts) {
  const ScratchDir dir;
  EXPECT_EQ(start_error("pty:" + dir.file("pod")), "");
  const uint16_t port = transport::testing::free_loopback_port(SOCK_DGRAM);
  EXPECT_EQ(start_error("udp://127.0.0.1:" + std::to_string(port)), "");
}

}  // namespace
}  // namespace k40t::sim
