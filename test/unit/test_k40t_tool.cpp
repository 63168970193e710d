// The k40t command-line tool, run as a program: help, argument errors (exit 2), decode of hex
// and of the sample capture, list.
#include <gtest/gtest.h>

#include <sys/socket.h>

#include <string>
#include <vector>

#include "golden_checks.h"
#include "run_tool.h"
#include "transport_test_support.h"

namespace k40t::test {
namespace {

using testing::golden_file_paths;
using testing::GoldenFrame;
using testing::read_golden_file;

// Section 3.2.5.1 request (see test_frame.cpp) and its ACK (see core_examples.txt).
const char* kLaserRequestHex = "FD 02 04 01 00 01 01 00 04 00 01 00 A2 56";
const char* kLaserAckHex = "FD 04 01 01 00 04 01 00 04 01 00 00 00 7B 82 9E";

TEST(K40tTool, HelpForTheToolAndEachCommand) {
  const ToolRun tool = run_k40t("--help");
  EXPECT_EQ(tool.exit_code, 0);
  for (const char* command : {"decode", "monitor", "send", "list", "probe"}) {
    EXPECT_NE(tool.out.find(std::string("  ") + command), std::string::npos) << command;
    const ToolRun help = run_k40t(std::string(command) + " --help");
    EXPECT_EQ(help.exit_code, 0) << command;
    EXPECT_NE(help.out.find(std::string("usage: k40t ") + command), std::string::npos) << help.out;
    EXPECT_TRUE(help.err.empty()) << help.err;
  }
}

struct BadCall {
  std::string arguments;
  std::string message;  // a piece of what stderr must say
};

TEST(K40tTool, BadArgumentsExitWithCodeTwoAndSayWhy) {
  const std::vector<BadCall> calls = {
      {"", "missing COMMAND"},
      {"frobnicate", "unknown command 'frobnicate'"},
      {"decode --hex 'FD 0G'", "invalid hex digit 'G' at character 5"},
      {"decode --hex 'FD 0'", "odd number of hex digits"},
      {"decode --hex", "option --hex needs a value"},
      {"decode --crc-coverage sometimes --hex FD",
       "crc_coverage must be auto, header_excluded or whole_frame"},
      {"decode --ack-byte-order middle --hex FD", "ack_byte_order must be big, little or auto"},
      {"decode --bogus", "unknown option '--bogus'"},
      {"decode a.bin b.bin", "give one input"},
      {"decode --hex FD file.bin", "not both"},
      {"monitor", "give one URL or capture FILE"},
      {"monitor ftp://host:1", "unknown scheme 'ftp'"},
      {"send", "give a link URL and a COMMAND"},
      {"send serial:///dev/null", "give a link URL and a COMMAND"},
      {"send serial:///dev/null warp_drive", "unknown message 'warp_drive'"},
      {"send serial:///dev/null gimbal_attitude", "is not a request the host sends"},
      {"send serial:///dev/null laser_range_ack", "is not a request the host sends"},
      {"send serial:///dev/null laser_range range=4",
       "laser_range has no field 'range'; its fields: enable"},
      {"send serial:///dev/null laser_range enable=maybe", "expected 0, 1, true or false"},
      {"send serial:///dev/null laser_range enable", "expected name=value, got 'enable'"},
      {"send serial:///dev/null laser_range enable=1 enable=0", "given twice"},
      {"send serial:///dev/null laser_range --timeout 0", "--timeout must be an integer 1..60000"},
      {"send serial:///dev/null laser_range --retries many", "--retries must be an integer 0..10"},
      {"send serial:///dev/null 0x0777", "not in the catalogue"},
      {"send serial:///dev/null 0x7777 --payload 0", "odd number of hex digits"},
      {"send serial:///dev/null 0x1000000 --payload 00", "is not a request id"},
      {"send serial:///dev/null laser_range enable=1 --payload 0100", "not both"},
      {"send nowhere laser_range", "nowhere"},
      {"list extra", "unexpected argument 'extra'"},
  };
  for (const BadCall& call : calls) {
    const ToolRun run = run_k40t(call.arguments);
    EXPECT_EQ(run.exit_code, 2) << "k40t " << call.arguments << "\n" << run.err;
    EXPECT_NE(run.err.find(call.message), std::string::npos) << "k40t " << call.arguments << "\n"
                                                             << run.err;
    EXPECT_TRUE(run.out.empty()) << "k40t " << call.arguments << "\n" << run.out;
  }
}

TEST(K40tTool, DecodeHexOptionPrintsOneJsonObjectPerFrame) {
  const ToolRun run =
      run_k40t(std::string("decode --hex '") + kLaserRequestHex + " " + kLaserAckHex + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(
      run.out,
      "{\"offset\":0,\"id\":\"0x000400\",\"name\":\"laser_range\",\"section\":\"3.2.5.1\",\"kind\":"
      "\"request\",\"direction\":\"host_to_pod\",\"src\":\"0x01/0x01\",\"dst\":\"0x04/"
      "0x01\",\"seq\":0,"
      "\"crc_coverage\":\"header_excluded\",\"payload\":\"01 00\",\"fields\":{\"enable\":true}}\n"
      "{\"offset\":14,\"id\":\"0x010400\",\"name\":\"laser_range_ack\",\"section\":\"3.2.5.1\","
      "\"kind\":"
      "\"ack\",\"direction\":\"pod_to_host\",\"src\":\"0x04/0x01\",\"dst\":\"0x01/0x01\",\"seq\":0,"
      "\"crc_coverage\":\"header_excluded\",\"payload\":\"00 00 00 "
      "7B\",\"fields\":{\"code\":{\"code\":0,"
      "\"name\":\"OK, success\"},\"distance_m\":12.3}}\n");
  EXPECT_NE(run.err.find("good frames 2, checksum errors 0"), std::string::npos) << run.err;
}

// --ack-byte-order auto: the first ACK whose bytes read sensibly one way only sets the order
// (docs/protocol/decisions.md#conventions). ACK 0x010012 (section 3.1.2.2) from the gimbal
// 0x03/0x01 to the host, SEQ 0, response code 0x0001 "failure" (section 3.3) low byte first: 01 00;
// the checksum is CRC-16/MCRF4XX of LEN..payload (A1), 0x775A, low byte first.
TEST(K40tTool, DecodeWithAutoAckByteOrderReadsALittleEndianCode) {
  const std::string frame = "FD 02 01 01 00 03 01 12 00 01 01 00 5A 77";
  const ToolRun automatic = run_k40t("decode --ack-byte-order auto --hex '" + frame + "'");
  ASSERT_EQ(automatic.exit_code, 0) << automatic.err;
  EXPECT_NE(automatic.out.find("\"fields\":{\"code\":{\"code\":1,"), std::string::npos)
      << automatic.out;
  const ToolRun big = run_k40t("decode --hex '" + frame + "'");
  EXPECT_NE(big.out.find("\"code\":256"), std::string::npos) << big.out;  // 0x0100
}

TEST(K40tTool, DecodeReadsHexFromStdinAndReportsUndecodablePayloads) {
  // 0x010400 with a one-byte payload (too short for the response code), then unknown id
  // 0x7F0001; checksums by test/data/frame_crc.py.
  const ToolRun run = run_k40t("decode -",
                               "FD 01 01 01 02 04 01 00 04 01 20 0A 0B\n0xFD, 0x00, 0x01, 0x01, "
                               "0x00, 0x04, 0x01, 0x01, 0x00, 0x7F, 0x75, 0xB0\n");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(
      run.out.find(
          "\"error\":\"laser_range_ack (0x010400): payload of 1 bytes is too short, need 2\""),
      std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("\"name\":null"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"error\":\"unknown message id 0x7F0001\""), std::string::npos)
      << run.out;
  EXPECT_NE(run.err.find("good frames 2"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("unknown ids 1"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("decode errors 1"), std::string::npos) << run.err;
}

// The laser request, then the ACK's first 10 of 16 bytes: the second frame is cut short.
TEST(K40tTool, DecodeSaysWhenTheInputEndsInsideAFrame) {
  const ToolRun run = run_k40t(std::string("decode --hex '") + kLaserRequestHex +
                               " FD 04 01 01 00 04 01 00 04 01'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("good frames 1"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("the input ends inside a frame: its last 10 bytes (from offset 14) start "
                         "a frame that is cut short"),
            std::string::npos)
      << run.err;
  const ToolRun whole = run_k40t(std::string("decode --hex '") + kLaserRequestHex + "'");
  EXPECT_EQ(whole.err.find("cut short"), std::string::npos) << whole.err;
}

// Over UDP the pod (and k40t_sim) answers the peer that last wrote to it; monitor never writes, so
// it hears nothing: after 2 s it says why instead of staying silent.
TEST(K40tTool, MonitorOverUdpHintsWhyNothingArrives) {
  const uint16_t port = transport::testing::free_loopback_port(SOCK_DGRAM);
  const std::string url = "udp://127.0.0.1:" + std::to_string(port);
  const ToolRun run =
      run_shell("timeout --preserve-status -s TERM 3 '" + k40t_path() + "' monitor " + url);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("nothing received from " + url + " in 2 s: over UDP the pod"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("stopped by SIGTERM"), std::string::npos) << run.err;
}

TEST(K40tTool, DecodeOfAMissingFileFails) {
  const ToolRun run = run_k40t("decode /nonexistent/capture.bin");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("cannot open '/nonexistent/capture.bin'"), std::string::npos) << run.err;
}

TEST(K40tTool, ListShowsTheCatalogue) {
  const ToolRun run = run_k40t("list --fields");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("0x000400   laser_range"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("enable (bool, default 1)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("0x010400   laser_range_ack"), std::string::npos);
}

// The (id, payload) pairs `k40t decode` printed, in order.
std::vector<std::string> decoded_frames(const std::string& json_lines) {
  std::vector<std::string> frames;
  size_t pos = 0;
  while ((pos = json_lines.find("\"id\":\"", pos)) != std::string::npos) {
    const std::string id = json_lines.substr(pos + 6, 8);
    const size_t payload = json_lines.find("\"payload\":\"", pos) + 11;
    frames.push_back(id + " " +
                     json_lines.substr(payload, json_lines.find('"', payload) - payload));
    pos = payload;
  }
  return frames;
}

// The same pairs from the golden files, in the capture script's order (file names sorted
// bytewise, as the script's sorted() does).
std::vector<std::string> golden_frames() {
  std::vector<std::string> frames;
  for (const std::string& path : golden_file_paths()) {
    Result<std::vector<GoldenFrame>> file = read_golden_file(path);
    EXPECT_TRUE(file) << file.error();
    if (!file) break;
    for (const GoldenFrame& g : file.value()) {
      const testing::SplitFrame split = testing::checked_split(g);
      char id[16];
      std::snprintf(id, sizeof(id), "0x%06X", static_cast<unsigned>(split.header.message_id));
      frames.push_back(std::string(id) + " " + testing::hex_bytes(split.payload));
    }
  }
  return frames;
}

TEST(SampleCapture, DecodeKeepsEveryGoldenFrameAndNothingElse) {
  const std::string capture = temp_path("capture.bin");
  const ToolRun built =
      run_shell(std::string("/usr/bin/python3 '") + K40T_TEST_DATA_DIR +
                "/../../scripts/make_sample_capture.py' --output '" + capture + "'");
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const ToolRun run = run_k40t("decode '" + capture + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> expected = golden_frames();
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(decoded_frames(run.out), expected);
  // The noise was there and was counted, not decoded.
  EXPECT_EQ(run.err.find("checksum errors 0,"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("length errors 0,"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("discarded bytes 0,"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("good frames " + std::to_string(expected.size()) + ","), std::string::npos)
      << run.err;

  // The committed demo capture is the one the script builds from today's golden files.
  EXPECT_TRUE(read_file(capture) ==
              read_file(std::string(K40T_TEST_DATA_DIR) + "/sample_capture.bin"))
      << "test/data/sample_capture.bin is out of date: run scripts/make_sample_capture.py";
  std::remove(capture.c_str());
}

TEST(SampleCapture, MonitorPrintsOneLinePerFrameAndTheCounters) {
  const ToolRun run =
      run_k40t(std::string("monitor '") + K40T_TEST_DATA_DIR + "/sample_capture.bin'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  size_t lines = 0;
  for (char c : run.out) lines += c == '\n';
  EXPECT_EQ(lines, golden_frames().size());
  EXPECT_NE(run.out.find("laser_range 0x01/0x01>0x04/0x01 #0 enable=1"), std::string::npos)
      << run.out;
  EXPECT_NE(run.err.find("good frames"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace k40t::test
