// `k40t probe` run as a program against the simulated pod playing each reading of
// docs/protocol/decisions.md#conventions (`k40t_sim --convention NAME=VALUE`): for every
// alternative of every reading the probe can learn, the parameter file it writes names that
// alternative; the readings it cannot settle stay comments with their default. Plus its errors:
// bad arguments, no link, a silent link, a refused gimbal command.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "k40t_driver/sim/pod_server.h"
#include "k40t_driver/sim/sim_options.h"
#include "run_tool.h"
#include "sim_link_harness.h"

namespace k40t::test {
namespace {

using sim::PodModel;

struct Written {
  std::string value;
  bool learned = false;  // a parameter line; false: a comment line (default kept)
};

// The parameter file: `name: value  # evidence` or `# name: value  # why`.
std::map<std::string, Written> parse_parameter_file(const std::string& text) {
  std::map<std::string, Written> readings;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const bool comment = line.rfind("# ", 0) == 0;
    const std::string body = comment ? line.substr(2) : line;
    const size_t colon = body.find(": ");
    if (colon == std::string::npos || body.find(' ') < colon) continue;  // the header line
    const size_t end = body.find("  #", colon);
    readings[body.substr(0, colon)] = {body.substr(colon + 2, end - colon - 2), !comment};
  }
  return readings;
}

struct ProbeCase {
  std::vector<std::string> sim_args;  // k40t_sim options, --link is added
  std::string probe_args;             // after URL --listen 1 --out FILE
  std::function<void(PodModel&)> setup;
  std::function<void(PodModel&)> after;        // checks on the simulator once the probe has run
  std::map<std::string, std::string> learned;  // reading -> the value the file must set
  std::map<std::string, std::string> kept;     // reading -> the default it must leave commented
};

// Starts the simulator, runs the probe against it, returns the file and checks it.
ToolRun probe_against_sim(const ProbeCase& c, std::map<std::string, Written>* file = nullptr) {
  const std::string pty = sim::testing::unique_pty_path();
  std::vector<std::string> args = c.sim_args;
  args.insert(args.end(), {"--link", "pty:" + pty});
  Result<sim::SimOptions> options = sim::parse_sim_options(args);
  EXPECT_TRUE(options) << options.error();
  if (!options) return {};
  options->pod.gimbal.drift_calibration_s = 1;  // one calibration, not five seconds of it
  sim::PodServer server(options.value());
  const Status started = server.start();
  EXPECT_TRUE(started) << started.message();
  if (c.setup) server.with_model(c.setup);
  const std::string out = temp_path("probe.yaml");
  const ToolRun run = run_k40t("probe 'serial://" + pty + "?baud=115200' --listen 1 --out '" + out +
                               "' " + c.probe_args);
  if (c.after) server.with_model(c.after);
  server.stop();
  const std::map<std::string, Written> written = parse_parameter_file(read_file(out));
  std::remove(out.c_str());
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  // A learned reading is a parameter line, a kept one a comment line.
  for (const auto& [expected, as_parameter] : {std::pair{&c.learned, true}, {&c.kept, false}}) {
    for (const auto& [name, value] : *expected) {
      const auto found = written.find(name);
      if (found == written.end()) {
        ADD_FAILURE() << name << " missing\n" << run.out << run.err;
        continue;
      }
      EXPECT_EQ(found->second.learned, as_parameter) << name << "\n" << run.out;
      EXPECT_EQ(found->second.value, value) << name << "\n" << run.out;
    }
  }
  if (file != nullptr) *file = written;
  return run;
}

// The readings no traffic shows, always comments with their defaults.
const std::map<std::string, std::string> kNeverLearned = {{"roll_sign", "right_down"},
                                                          {"attitude_order", "zyx"},
                                                          {"photo_mode_2", "time_lapse"},
                                                          {"gps_request_time", "utc"},
                                                          {"gps_answer_byte_order", "ack"},
                                                          {"laser_target_zeros", "no_return"},
                                                          {"focus_plus", "near"}};

TEST(K40tProbe, LearnsTheDefaultReadingsWithMotionAndCalibration) {
  ProbeCase c;
  c.probe_args = "--allow-motion --calibration --sd-card-gb 64";
  c.setup = [](PodModel& pod) {
    pod.thermal().settings().reported.enhancement_on = true;  // bit 7 and level 5
    pod.thermal().settings().reported.enhancement_level = 5;
    pod.thermal().settings().reported.zoom_x = 8;  // 8 is a ratio only
    pod.gimbal().command_angles(-10, 20);          // off centre: centred, then brought back
    pod.camera().visible().shutter = protocol::Shutter::k1_4;  // 1/4 s saturates "us" at 65535
  };
  c.after = [](PodModel& pod) {
    EXPECT_NEAR(pod.gimbal().pose().joint_deg.yaw, 20, 0.1);
    EXPECT_NEAR(pod.gimbal().pose().joint_deg.pitch, -10, 0.1);
  };
  c.learned = {{"crc_coverage", "header_excluded"},
               {"ack_byte_order", "big"},
               {"gimbal_system_id", "3"},
               {"camera_system_id", "4"},
               {"angle_command_scale", "100"},
               {"yaw_sign", "right"},
               {"pitch_sign", "up"},
               {"yaw_range", "signed"},
               {"sd_capacity_unit", "10mb"},
               {"enhancement_switch", "bit7"},
               {"thermal_zoom_code", "ratio"},
               {"calibration_end", "status"}};
  c.learned["shutter_field"] = "us";
  c.kept = kNeverLearned;
  const ToolRun run = probe_against_sim(c);
  EXPECT_NE(run.out.find("gimbal version (0x000018): code=ok_success(0) hardware_major=1"),
            std::string::npos)
      << run.out;
}

TEST(K40tProbe, LearnsTheOtherReadingOfEveryItem) {
  ProbeCase c;
  c.sim_args = {"--crc-coverage",     "whole_frame",
                "--ack-byte-order",   "little",
                "--angle-scale",      "10",
                "--gimbal-system-id", "5",
                "--sd-capacity-mb",   "4000",
                "--convention",       "camera_system_id=6",
                "--convention",       "yaw_sign=left",
                "--convention",       "pitch_sign=down",
                "--convention",       "yaw_range=heading",
                "--convention",       "sd_capacity_unit=0.1mb",
                "--convention",       "shutter_field=100us",
                "--convention",       "calibration_end=ack",
                "--convention",       "thermal_zoom_code=zero_based",
                "--convention",       "enhancement_switch=bit0"};
  c.probe_args = "--allow-motion --calibration --sd-card-gb 4";
  c.setup = [](PodModel& pod) {
    pod.thermal().settings().reported.enhancement_on = true;  // bit 0 and level 5 (bits 7..1)
    pod.thermal().settings().reported.enhancement_level = 5;
  };
  c.learned = {{"crc_coverage", "whole_frame"}, {"ack_byte_order", "little"},
               {"gimbal_system_id", "5"},       {"camera_system_id", "6"},
               {"angle_command_scale", "10"},   {"yaw_sign", "left"},
               {"pitch_sign", "down"},          {"yaw_range", "heading"},
               {"sd_capacity_unit", "0.1mb"},   {"shutter_field", "100us"},
               {"enhancement_switch", "bit0"},  {"thermal_zoom_code", "zero_based"},
               {"calibration_end", "ack"}};
  c.kept = kNeverLearned;
  const ToolRun run = probe_against_sim(c);
  // The read-backs are shown in the byte order learned (0x010502's 1811 is 07 13 little-endian).
  EXPECT_NE(run.out.find("max_value=1811 min_value=172"), std::string::npos) << run.out;
}

TEST(K40tProbe, LearnsTheThirdReadingsReadOnly) {
  ProbeCase c;
  c.sim_args = {"--convention", "shutter_field=us_wrapped",
                "--convention", "enhancement_switch=level",
                "--convention", "sd_capacity_unit=0.1mb"};
  c.setup = [](PodModel& pod) {
    pod.camera().visible().shutter = protocol::Shutter::k1_4;  // 250000 us: wraps to 53392
    pod.thermal().settings().reported.enhancement_on = true;   // the byte is the level: 10
    pod.thermal().settings().reported.enhancement_level = 10;
  };
  // A 64 GB card in 0.1 MB counts saturates at 65535; without motion, signs and scale stay.
  c.learned = {{"shutter_field", "us_wrapped"},
               {"enhancement_switch", "level"},
               {"sd_capacity_unit", "0.1mb"}};
  c.kept = {{"yaw_sign", "right"},
            {"pitch_sign", "up"},
            {"angle_command_scale", "100"},
            {"calibration_end", "auto"}};
  const ToolRun run = probe_against_sim(c);
  EXPECT_NE(run.out.find("not learned: run with --allow-motion"), std::string::npos) << run.out;
}

TEST(K40tProbe, BadArgumentsExitTwoBeforeAnythingIsSent) {
  const std::vector<std::pair<std::string, std::string>> calls = {
      {"probe", "give one link URL"},
      {"probe ftp://host:1", "unknown scheme 'ftp'"},
      {"probe serial:///dev/null --listen 0", "--listen must be an integer 1..60"},
      {"probe serial:///dev/null --sd-card-gb big", "--sd-card-gb must be a number"},
      {"probe serial:///dev/null --out /nonexistent/dir/pod.yaml", "cannot write"},
      {"probe serial:///dev/null --allow-motion=1", "takes no value"},
  };
  for (const auto& [arguments, message] : calls) {
    const ToolRun run = run_k40t(arguments);
    EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.err;
    EXPECT_NE(run.err.find(message), std::string::npos) << arguments << "\n" << run.err;
  }
}

// A UDP port nobody serves: the link opens (UDP has no connection) but no frame ever comes.
int free_udp_port() {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address));
  socklen_t size = sizeof(address);
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size);
  ::close(fd);
  return ntohs(address.sin_port);
}

TEST(K40tProbe, NoLinkOrNoFrameExitsOneWithOneLine) {
  const ToolRun missing = run_k40t("probe serial:///nonexistent/k40t_tty --connect-timeout 300");
  EXPECT_EQ(missing.exit_code, 1) << missing.err;
  EXPECT_NE(missing.err.find("not connected after 300 ms"), std::string::npos) << missing.err;
  const ToolRun silent =
      run_k40t("probe udp://127.0.0.1:" + std::to_string(free_udp_port()) + " --listen 1");
  EXPECT_EQ(silent.exit_code, 1) << silent.err;
  EXPECT_NE(silent.err.find("no frame from the pod in 1 s"), std::string::npos) << silent.err;
  EXPECT_EQ(std::count(silent.err.begin(), silent.err.end(), '\n'), 1) << silent.err;
}

TEST(K40tProbe, ARefusedGimbalCommandStopsTheMotionAndWritesNothing) {
  const std::string pty = sim::testing::unique_pty_path();
  sim::SimOptions options;
  options.link = "pty://" + pty;
  options.faults.refuse_id = 0x000012;
  sim::PodServer server(options);
  ASSERT_TRUE(server.start());
  const std::string out = temp_path("refused.yaml");
  const ToolRun run = run_k40t("probe 'serial://" + pty + "?baud=115200' --listen 1 --out '" + out +
                               "' --allow-motion");
  server.stop();
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_NE(run.err.find("stopped: 0x000012 pitch none 0, yaw right 1: refused"), std::string::npos)
      << run.err;
  EXPECT_EQ(::access(out.c_str(), F_OK), -1) << "a file was written";
}

}  // namespace
}  // namespace k40t::test
