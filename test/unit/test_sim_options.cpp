// k40t_sim's command line.
#include <gtest/gtest.h>

#include "k40t_driver/sim/sim_options.h"

namespace k40t::sim {
namespace {

TEST(SimOptions, DefaultsServeAPtyWithNotesDefaults) {
  const auto options = parse_sim_options({});
  ASSERT_TRUE(options) << options.error();
  EXPECT_EQ(options->link, "pty:///tmp/k40t_pod");
  EXPECT_EQ(options->crc_coverage, protocol::CrcCoverage::kHeaderExcluded);
  EXPECT_EQ(options->codec.ack_byte_order, protocol::ByteOrder::kBig);
  EXPECT_FALSE(options->help);
}

TEST(SimOptions, LinksAreTurnedIntoTheirServerSide) {
  EXPECT_EQ(*server_side_url("pty:/tmp/k40t_pod"), "pty:///tmp/k40t_pod");
  EXPECT_EQ(*server_side_url("pty:///tmp/x"), "pty:///tmp/x");
  EXPECT_EQ(*server_side_url("udp://127.0.0.1:14550"), "udp-server://127.0.0.1:14550");
  EXPECT_EQ(*server_side_url("tcp://127.0.0.1:5760"), "tcp-server://127.0.0.1:5760");
  EXPECT_EQ(*server_side_url("tcp-server://127.0.0.1:5760"), "tcp-server://127.0.0.1:5760");
  const auto bad = server_side_url("serial:///dev/ttyUSB0");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("serial:///dev/ttyUSB0"), std::string::npos);
}

TEST(SimOptions, EveryKindOfOptionIsParsed) {
  const auto options = parse_sim_options({"--link",
                                          "udp://127.0.0.1:9000",
                                          "--crc-coverage=whole_frame",
                                          "--ack-byte-order",
                                          "little",
                                          "--ground-height",
                                          "50",
                                          "--corrupt-rate",
                                          "0.01",
                                          "--garbage-rate",
                                          "0.1",
                                          "--drop-ack-rate",
                                          "0.2",
                                          "--delay-ack-ms",
                                          "300",
                                          "--silence",
                                          "5:2",
                                          "--disconnect",
                                          "10:1.5",
                                          "--seq-jump",
                                          "3:7",
                                          "--seed",
                                          "9",
                                          "--capture",
                                          "/tmp/cap",
                                          "--control",
                                          "tcp:127.0.0.1:5761",
                                          "--sd",
                                          "absent",
                                          "--single-shot-status",
                                          "--sd-capacity-mb",
                                          "1000"});
  ASSERT_TRUE(options) << options.error();
  EXPECT_EQ(options->link, "udp-server://127.0.0.1:9000");
  EXPECT_EQ(options->crc_coverage, protocol::CrcCoverage::kWholeFrame);
  EXPECT_EQ(options->codec.ack_byte_order, protocol::ByteOrder::kLittle);
  EXPECT_DOUBLE_EQ(options->pod.world.ground_height_m, 50);
  EXPECT_DOUBLE_EQ(options->faults.corrupt_rate, 0.01);
  EXPECT_DOUBLE_EQ(options->faults.garbage_rate, 0.1);
  EXPECT_DOUBLE_EQ(options->faults.drop_ack_rate, 0.2);
  EXPECT_DOUBLE_EQ(options->faults.delay_ack_ms, 300);
  ASSERT_EQ(options->scheduled.size(), 3u);
  EXPECT_EQ(options->scheduled[0].kind, ScheduledFault::Kind::kSilence);
  EXPECT_EQ(options->scheduled[0].at.count(), 5000);
  EXPECT_DOUBLE_EQ(options->scheduled[1].amount, 1.5);
  EXPECT_EQ(options->scheduled[2].kind, ScheduledFault::Kind::kSequenceJump);
  EXPECT_EQ(options->seed, 9u);
  EXPECT_EQ(*options->capture_prefix, "/tmp/cap");
  EXPECT_EQ(*options->control_endpoint, "tcp:127.0.0.1:5761");
  EXPECT_EQ(*options->sd_condition, "absent");
  EXPECT_TRUE(options->pod.camera.single_shot_status);
  EXPECT_DOUBLE_EQ(options->pod.camera.sd.capacity_mb, 1000);
}

TEST(SimOptions, TheVideoKeyFrameIntervalIsSettable) {
  EXPECT_EQ(parse_sim_options({})->rtsp_key_interval, 30);
  const auto options = parse_sim_options({"--rtsp-port", "0", "--rtsp-key-interval", "15"});
  ASSERT_TRUE(options) << options.error();
  EXPECT_EQ(options->rtsp_key_interval, 15);
  EXPECT_FALSE(parse_sim_options({"--rtsp-key-interval", "0"}));
}

TEST(SimOptions, RoslaunchArgumentsAreIgnored) {
  const auto options =
      parse_sim_options({"__name:=pod_sim", "--help", "__log:=/tmp/log/pod_sim-1.log"});
  ASSERT_TRUE(options) << options.error();
  EXPECT_TRUE(options->help);
}

TEST(SimOptions, BadArgumentsAreNamed) {
  EXPECT_EQ(parse_sim_options({"--frobnicate"}).error(),
            "unknown argument '--frobnicate' (see --help)");
  EXPECT_EQ(parse_sim_options({"--corrupt-rate", "2"}).error(),
            "--corrupt-rate must be 0..1, got 2");
  EXPECT_EQ(parse_sim_options({"--ground-height"}).error(), "--ground-height: missing M");
  EXPECT_EQ(parse_sim_options({"--help=yes"}).error(), "--help: takes no value");
  EXPECT_NE(parse_sim_options({"--crc-coverage", "auto"}).error().find("not auto"),
            std::string::npos);
  EXPECT_NE(parse_sim_options({"--ack-byte-order", "middle"}).error().find("middle"),
            std::string::npos);
  // The driver's ack_byte_order: auto has no place in a pod, which sends one order.
  EXPECT_NE(parse_sim_options({"--ack-byte-order", "auto"}).error().find("got 'auto'"),
            std::string::npos);
  EXPECT_NE(parse_sim_options({"--convention", "ack_byte_order=auto"}).error().find("not auto"),
            std::string::npos);
  EXPECT_NE(parse_sim_options({"--silence", "5"}).error().find("AT:AMOUNT"), std::string::npos);
  EXPECT_NE(parse_sim_options({"--sd", "wet"}).error().find("wet"), std::string::npos);
}

// docs/protocol/decisions.md#conventions: the readings the pod follows, by the names of the
// driver's parameters; a bad name or value is refused with what is accepted.
TEST(SimOptions, ConventionsAreRepeatableAndCheckedByName) {
  Result<SimOptions> o =
      parse_sim_options({"--convention", "yaw_sign=left", "--convention", "sd_capacity_unit=0.1mb",
                         "--convention=ack_byte_order=little"});
  ASSERT_TRUE(o) << o.error();
  EXPECT_EQ(o->codec.conventions.yaw_sign, protocol::YawSign::kLeft);
  EXPECT_EQ(o->codec.conventions.sd_capacity_unit, protocol::SdCapacityUnit::kTenthMb);
  EXPECT_EQ(o->codec.ack_byte_order, protocol::ByteOrder::kLittle);
  EXPECT_EQ(parse_sim_options({"--convention", "yaw_sign=up"}).error(),
            "--convention: yaw_sign must be right or left, got 'up'");
  EXPECT_NE(
      parse_sim_options({"--convention", "yaw_sing=left"}).error().find("no convention named"),
      std::string::npos);
  EXPECT_NE(parse_sim_options({"--convention", "yaw_range=auto"}).error().find("not auto"),
            std::string::npos);
  EXPECT_NE(parse_sim_options({"--convention", "yaw_sign"}).error().find("NAME=VALUE"),
            std::string::npos);
}

// 0x000012 carries 180 deg of yaw in a uint16 only up to a scale of 364 (65535 / 180).
TEST(SimOptions, AnAngleScaleTooLargeForTheMagnitudeIsRefused) {
  EXPECT_EQ(parse_sim_options({"--angle-scale", "365"}).error(),
            "--angle-scale must be 1..364, got 365");
  const auto most = parse_sim_options({"--angle-scale", "364"});
  ASSERT_TRUE(most) << most.error();
  EXPECT_EQ(most->codec.angle_command_scale, 364);
}

TEST(SimOptions, UsageListsEveryOption) {
  const std::string usage = sim_usage();
  for (const char* option :
       {"--link", "--crc-coverage", "--ack-byte-order", "--corrupt-rate", "--garbage-rate",
        "--drop-ack-rate", "--delay-ack-ms", "--silence", "--disconnect", "--seq-jump", "--capture",
        "--control", "--convention", "--help"}) {
    EXPECT_NE(usage.find(option), std::string::npos) << option;
  }
}

}  // namespace
}  // namespace k40t::sim
