// UDP and TCP transports on 127.0.0.1 with ports chosen free at run time: round trips, the
// server-side rules (reply to the last UDP peer, newest TCP client wins), and reconnection after
// a TCP server restart.
#include <arpa/inet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "transport_test_support.h"

namespace k40t::transport {
namespace {

using testing::Endpoint;
using testing::free_loopback_port;
using ::testing::HasSubstr;
using testing::random_bytes;

std::string loopback(uint16_t port) {
  return "127.0.0.1:" + std::to_string(port);
}

void open_and_wait_connected(Endpoint& endpoint) {
  ASSERT_TRUE(endpoint.transport->open()) << endpoint.transport->url();
  ASSERT_TRUE(endpoint.log.wait_for(LinkState::kConnected))
      << endpoint.transport->url() << ": " << endpoint.transport->stats().last_error;
}

void expect_delivered(Endpoint& from, Endpoint& to, const std::vector<uint8_t>& bytes) {
  to.received.clear();
  const Status sent = from.send(bytes);
  ASSERT_TRUE(sent) << sent.message();
  ASSERT_TRUE(to.received.wait_for_size(bytes.size()))
      << "got " << to.received.size() << " of " << bytes.size();
  EXPECT_EQ(to.received.bytes(), bytes);
}

TEST(UdpTransport, ClientAndServerRoundTrip) {
  const uint16_t port = free_loopback_port(SOCK_DGRAM);
  Endpoint server("udp-server://" + loopback(port));
  Endpoint client("udp://" + loopback(port));
  open_and_wait_connected(server);
  open_and_wait_connected(client);

  const Status early = server.send({1, 2});
  ASSERT_FALSE(early) << "a udp-server has nobody to reply to before the first datagram";
  EXPECT_THAT(early.message(), HasSubstr("no peer"));
  EXPECT_THAT(early.message(), HasSubstr(loopback(port)));

  expect_delivered(client, server, {0xFD, 0x11, 0x22});
  expect_delivered(server, client, {0xFD, 0x33});
  // One datagram bigger than any pty read: datagrams must not be truncated.
  expect_delivered(client, server, random_bytes(60000, 6));
  EXPECT_EQ(server.received.callbacks(), 1u);

  const LinkStats stats = client.transport->stats();
  EXPECT_EQ(stats.writes, 2u);
  EXPECT_EQ(stats.bytes_sent, 60003u);
  EXPECT_EQ(stats.bytes_received, 2u);
  EXPECT_EQ(stats.reads, 1u);
  EXPECT_EQ(server.transport->stats().send_errors, 1u);
}

TEST(UdpTransport, ClientBindsToTheRequestedLocalAddress) {
  // A plain socket stands in for the pod so the test can see the datagram's source port.
  testing::LoopbackSocket pod(SOCK_DGRAM);
  const uint16_t local_port = free_loopback_port(SOCK_DGRAM);

  const timeval generous{15, 0};  // a broken transport fails the test instead of hanging it
  ASSERT_EQ(::setsockopt(pod.fd(), SOL_SOCKET, SO_RCVTIMEO, &generous, sizeof generous), 0);

  Endpoint client("udp://" + loopback(pod.port()) + "?bind=" + loopback(local_port));
  open_and_wait_connected(client);
  ASSERT_TRUE(client.send({0xAB}));
  uint8_t byte = 0;
  sockaddr_in from{};
  socklen_t from_length = sizeof from;
  ASSERT_EQ(::recvfrom(pod.fd(), &byte, 1, 0, reinterpret_cast<sockaddr*>(&from), &from_length), 1);
  EXPECT_EQ(byte, 0xAB);
  EXPECT_EQ(ntohs(from.sin_port), local_port);
}

TEST(UdpTransport, ServerRepliesToTheMostRecentPeer) {
  const uint16_t port = free_loopback_port(SOCK_DGRAM);
  Endpoint server("udp-server://" + loopback(port));
  Endpoint first("udp://" + loopback(port));
  Endpoint second("udp://" + loopback(port));
  open_and_wait_connected(server);
  open_and_wait_connected(first);
  open_and_wait_connected(second);
  expect_delivered(first, server, {1});
  expect_delivered(second, server, {2});
  expect_delivered(server, second, {3});
  EXPECT_EQ(first.received.size(), 0u);
}

TEST(UdpTransport, ServerPortInUseIsRetriedWithTheReason) {
  testing::LoopbackSocket holder(SOCK_DGRAM);
  const uint16_t port = holder.port();

  Endpoint server("udp-server://" + loopback(port));
  ASSERT_TRUE(server.transport->open());
  ASSERT_TRUE(server.log.wait_for(LinkState::kReconnecting));
  EXPECT_THAT(server.transport->stats().last_error, HasSubstr("Address already in use"));
  EXPECT_THAT(server.transport->stats().last_error, HasSubstr(loopback(port)));
  holder.close();
  ASSERT_TRUE(server.log.wait_for(LinkState::kConnected)) << server.transport->stats().last_error;
}

class TcpPair : public ::testing::Test {
 protected:
  void SetUp() override {
    // A tcp-server is "connecting" until it has accepted a client.
    ASSERT_TRUE(server.transport->open());
    ASSERT_TRUE(testing::eventually([&] { return server.log.count(LinkState::kConnecting) == 1; }));
    EXPECT_EQ(server.transport->state(), LinkState::kConnecting);
    open_and_wait_connected(client);
    ASSERT_TRUE(server.log.wait_for(LinkState::kConnected)) << server.transport->stats().last_error;
  }

  const uint16_t port = free_loopback_port(SOCK_STREAM);
  Endpoint server{"tcp-server://" + loopback(port)};
  Endpoint client{"tcp://" + loopback(port)};
};

TEST_F(TcpPair, RoundTripWithLargePayloads) {
  expect_delivered(client, server, {0xFD, 0x01});
  expect_delivered(server, client, {0xFD, 0x02});
  expect_delivered(client, server, random_bytes(300 * 1024, 7));
  expect_delivered(server, client, random_bytes(300 * 1024, 8));
  EXPECT_GT(client.received.callbacks(), 1u);
  const LinkStats stats = client.transport->stats();
  EXPECT_EQ(stats.writes, 2u);
  EXPECT_EQ(stats.bytes_sent, 2u + 300 * 1024);
  EXPECT_EQ(stats.bytes_received, 2u + 300 * 1024);
  EXPECT_EQ(stats.connects, 1u);
}

TEST_F(TcpPair, ClientReconnectsAfterServerRestart) {
  server.transport->close();
  ASSERT_TRUE(client.log.wait_for(LinkState::kReconnecting));
  EXPECT_THAT(client.transport->stats().last_error, HasSubstr("tcp://" + loopback(port)));
  // While the server is down, the attempts fail with the reason.
  ASSERT_TRUE(testing::eventually([&] {
    return client.transport->stats().last_error.find("Connection refused") != std::string::npos;
  }));
  ASSERT_TRUE(server.transport->open());
  ASSERT_TRUE(client.log.wait_for(LinkState::kConnected, 2))
      << client.transport->stats().last_error;
  ASSERT_TRUE(server.log.wait_for(LinkState::kConnected, 2));
  expect_delivered(client, server, {0x55});
  expect_delivered(server, client, {0x66});
  const LinkStats stats = client.transport->stats();
  EXPECT_EQ(stats.connects, 2u);
  EXPECT_EQ(stats.disconnects, 1u);
}

TEST_F(TcpPair, ServerNoticesTheClientLeavingAndAcceptsTheNextOne) {
  client.transport->close();
  ASSERT_TRUE(server.log.wait_for(LinkState::kReconnecting));
  EXPECT_THAT(server.transport->stats().last_error, HasSubstr("end of file"));
  EXPECT_FALSE(server.send({1})) << "no client to send to";
  ASSERT_TRUE(client.transport->open());
  ASSERT_TRUE(server.log.wait_for(LinkState::kConnected, 2));
  ASSERT_TRUE(client.log.wait_for(LinkState::kConnected, 2));
  expect_delivered(server, client, {0x77});
}

TEST_F(TcpPair, NewClientReplacesTheOldOne) {
  // Reopen the first client with a back-off far longer than the test, so that once replaced it
  // stays away instead of taking the server back (close() still ends its wait at once).
  client.transport->close();
  ReconnectPolicy patient;
  patient.initial_delay = std::chrono::minutes(10);
  patient.max_delay = patient.initial_delay;
  client.transport->set_reconnect_policy(patient);
  ASSERT_TRUE(client.transport->open());
  ASSERT_TRUE(client.log.wait_for(LinkState::kConnected, 2));
  ASSERT_TRUE(testing::eventually([&] { return server.transport->stats().connects == 2; }));

  Endpoint newcomer("tcp://" + loopback(port));
  open_and_wait_connected(newcomer);
  ASSERT_TRUE(testing::eventually([&] { return server.transport->stats().connects == 3; }));
  EXPECT_THAT(server.log.last_reason(LinkState::kReconnecting), HasSubstr("new client"));
  ASSERT_TRUE(client.log.wait_for(LinkState::kReconnecting, 1)) << "the old client is dropped";
  expect_delivered(newcomer, server, {0x88});
  expect_delivered(server, newcomer, {0x99});
  EXPECT_EQ(client.received.size(), 0u);
}

TEST(TcpTransport, ClientWithoutServerKeepsRetryingUntilClosed) {
  const uint16_t port = free_loopback_port(SOCK_STREAM);
  Endpoint client("tcp://" + loopback(port));
  ASSERT_TRUE(client.transport->open());
  ASSERT_TRUE(client.log.wait_for(LinkState::kReconnecting));
  EXPECT_THAT(client.transport->stats().last_error, HasSubstr("Connection refused"));
  const Status sent = client.send({1});
  ASSERT_FALSE(sent);
  EXPECT_THAT(sent.message(), HasSubstr("tcp://" + loopback(port)));
  client.transport->close();
  client.transport->close();
  EXPECT_EQ(client.transport->state(), LinkState::kClosed);
  EXPECT_EQ(client.log.states().back(), LinkState::kClosed);
}

}  // namespace
}  // namespace k40t::transport
