// Device URLs: what parses, and that every malformed URL is rejected with a message naming the URL
// and the problem (through make_transport, the way users meet these errors).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "k40t_driver/transport/device_url.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::transport {
namespace {

using ::testing::HasSubstr;

TEST(DeviceUrl, SerialPathAndBaud) {
  auto url = parse_device_url("serial:///dev/ttyUSB0?baud=921600", {UrlForm::kPath, {"baud"}});
  ASSERT_TRUE(url) << url.error();
  EXPECT_EQ(url->scheme, "serial");
  EXPECT_EQ(url->path, "/dev/ttyUSB0");
  EXPECT_EQ(url->host, "");
  EXPECT_EQ(url->query_value("baud"), "921600");
  EXPECT_FALSE(url->query_value("parity").has_value());
}

TEST(DeviceUrl, HostPortAndQuery) {
  auto url = parse_device_url("udp://192.168.144.64:5000?bind=0.0.0.0:5001",
                              {UrlForm::kHostPort, {"bind"}});
  ASSERT_TRUE(url) << url.error();
  EXPECT_EQ(url->scheme, "udp");
  EXPECT_EQ(url->host, "192.168.144.64");
  EXPECT_EQ(url->port, 5000);
  EXPECT_EQ(url->path, "");
  EXPECT_EQ(url->query_value("bind"), "0.0.0.0:5001");
}

TEST(DeviceUrl, BracketedIpv6HostAndTrailingSlash) {
  auto url = parse_device_url("tcp://[::1]:65535/", {UrlForm::kHostPort, {}});
  ASSERT_TRUE(url) << url.error();
  EXPECT_EQ(url->host, "::1");
  EXPECT_EQ(url->port, 65535);
}

TEST(DeviceUrl, HostPortHelper) {
  auto parsed = parse_host_port("127.0.0.1:1");
  ASSERT_TRUE(parsed) << parsed.error();
  EXPECT_EQ(parsed->host, "127.0.0.1");
  EXPECT_EQ(parsed->port, 1);
  EXPECT_THAT(parse_host_port("127.0.0.1").error(), HasSubstr("missing port"));
  EXPECT_THAT(parse_host_port("::1:80").error(), HasSubstr("needs brackets"));
  EXPECT_THAT(parse_host_port("[::1:80").error(), HasSubstr("unterminated"));
}

TEST(DeviceUrl, KnownSchemesAreTheTable) {
  EXPECT_EQ(known_schemes(),
            (std::vector<std::string>{"serial", "pty", "udp", "udp-server", "tcp", "tcp-server"}));
}

TEST(DeviceUrl, EveryGoodExampleMakesATransport) {
  for (const std::string url :
       {"serial:///dev/ttyUSB0", "serial:///dev/ttyUSB0?baud=9600", "pty:///tmp/k40t_pod",
        "udp://127.0.0.1:5000", "udp://localhost:5000?bind=127.0.0.1:5001",
        "udp-server://0.0.0.0:5000", "tcp://127.0.0.1:2000", "tcp-server://127.0.0.1:2000"}) {
    auto made = make_transport(url);
    ASSERT_TRUE(made) << made.error();
    EXPECT_EQ((*made)->url(), url);
    EXPECT_EQ((*made)->state(), LinkState::kClosed);
  }
}

TEST(DeviceUrl, SerialWireTimeFollowsTheBaud) {
  auto made = make_transport("serial:///dev/ttyUSB0?baud=9600");
  ASSERT_TRUE(made) << made.error();
  EXPECT_DOUBLE_EQ((*made)->seconds_per_byte(), 10.0 / 9600);
  auto default_baud = make_transport("serial:///dev/ttyUSB0");
  ASSERT_TRUE(default_baud) << default_baud.error();
  EXPECT_DOUBLE_EQ((*default_baud)->seconds_per_byte(), 10.0 / 115200);  // protocol doc, 2.2
  auto network = make_transport("udp://127.0.0.1:5000");
  ASSERT_TRUE(network) << network.error();
  EXPECT_EQ((*network)->seconds_per_byte(), 0.0);
}

struct BadUrl {
  std::string url;
  std::string problem;  // a phrase the error must contain
};

class BadDeviceUrl : public ::testing::TestWithParam<BadUrl> {};

TEST_P(BadDeviceUrl, IsRejectedWithAMessageNamingUrlAndProblem) {
  const BadUrl& bad = GetParam();
  auto made = make_transport(bad.url);
  ASSERT_FALSE(made) << bad.url << " was accepted";
  EXPECT_THAT(made.error(), HasSubstr("\"" + bad.url + "\"")) << made.error();
  EXPECT_THAT(made.error(), HasSubstr(bad.problem)) << made.error();
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, BadDeviceUrl,
    ::testing::Values(
        BadUrl{"", "empty URL"}, BadUrl{"/dev/ttyUSB0", "no scheme"},
        BadUrl{"://x:1", "empty scheme"}, BadUrl{"Serial:///dev/ttyUSB0", "lower-case"},
        BadUrl{"bluetooth://aa:bb", "unknown scheme 'bluetooth'"},
        BadUrl{"carrier-pigeon:///coop", "known: serial, pty, udp, udp-server, tcp, tcp-server"},
        BadUrl{"udp://127.0.0.1", "missing port"}, BadUrl{"tcp://127.0.0.1:", "missing port"},
        BadUrl{"tcp://:2000", "missing host"}, BadUrl{"tcp-server://", "missing host"},
        BadUrl{"udp://127.0.0.1:0", "port 0 is out of range 1..65535"},
        BadUrl{"udp://127.0.0.1:65536", "port 65536 is out of range 1..65535"},
        BadUrl{"tcp://127.0.0.1:http", "port 'http' is not a number"},
        BadUrl{"tcp://127.0.0.1:-5", "port '-5' is not a number"},
        BadUrl{"tcp://127.0.0.1:2000/pod", "unexpected path '/pod'"},
        BadUrl{"serial://", "empty path"}, BadUrl{"pty:///", "empty path"},
        BadUrl{"serial://dev/ttyUSB0", "unexpected host 'dev'"},
        BadUrl{"serial:///dev/ttyUSB0?baud=12345", "baud '12345' is not a standard rate"},
        BadUrl{"serial:///dev/ttyUSB0?baud=fast", "one of 50, 75, 110"},
        BadUrl{"serial:///dev/ttyUSB0?baud=99999999999", "4000000)"},
        BadUrl{"serial:///dev/ttyUSB0?parity=even", "unknown query parameter 'parity'"},
        BadUrl{"serial:///dev/ttyUSB0?speed=9600", "(known: baud)"},
        BadUrl{"tcp://127.0.0.1:2000?bind=127.0.0.1:3000", "it takes none"},
        BadUrl{"serial:///dev/ttyUSB0?baud", "has no '='"},
        BadUrl{"serial:///dev/ttyUSB0?baud=", "'baud' has no value"},
        BadUrl{"serial:///dev/ttyUSB0?=9600", "has no name"},
        BadUrl{"serial:///dev/ttyUSB0?", "empty query"},
        BadUrl{"serial:///dev/ttyUSB0?baud=9600&", "stray '&'"},
        BadUrl{"serial:///dev/ttyUSB0?baud=9600&baud=115200", "'baud' is given twice"},
        BadUrl{"udp://127.0.0.1:5000?bind=127.0.0.1", "bind: missing port"},
        BadUrl{"udp://127.0.0.1:5000?bind=127.0.0.1:70000", "bind: port 70000 is out of range"},
        BadUrl{"serial:///dev/tty USB0", "white space"}));

TEST(DeviceUrl, BaudIsAddedToSerialUrlsOnly) {
  EXPECT_EQ(device_url_with_baud("serial:///dev/ttyUSB0", 115200),
            "serial:///dev/ttyUSB0?baud=115200");
  EXPECT_EQ(device_url_with_baud("serial:///dev/ttyUSB0?x=1", 9600),
            "serial:///dev/ttyUSB0?x=1&baud=9600");
  EXPECT_EQ(device_url_with_baud("serial:///dev/ttyS1?baud=57600", 115200),
            "serial:///dev/ttyS1?baud=57600");
  EXPECT_EQ(device_url_with_baud("udp://192.168.144.64:2000", 115200), "udp://192.168.144.64:2000");
}

}  // namespace
}  // namespace k40t::transport
