// `k40t bag --jsonl / --csv`'s exports (tools/k40t_bag/frame_export.h), ROS-free, with the
// hand-written gimbal attitude frame of the golden files (3.1.1.2): one CSV file per message named
// after it, the frame's header and its decoded fields as columns; one JSON object per line.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "frame_export.h"
#include "golden_file.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::driver {
namespace {

std::vector<uint8_t> golden_attitude() {
  Result<std::vector<testing::GoldenFrame>> frames =
      testing::read_golden_file(testing::golden_path("gimbal_laser_sbus.txt"));
  EXPECT_TRUE(frames) << frames.error();
  if (frames) {
    for (const testing::GoldenFrame& frame : frames.value()) {
      if (frame.name == "gimbal_attitude") return frame.bytes;
    }
  }
  ADD_FAILURE() << "no gimbal_attitude frame in gimbal_laser_sbus.txt";
  return {};
}

// Feeds the frame to `write` as the bag decoder does: bag "flight,1", topic /k40t/raw/rx.
void export_frame(FrameExport& out, const std::vector<uint8_t>& bytes) {
  protocol::FrameParser parser(protocol::CrcCoverage::kHeaderExcluded);
  const std::string bag = "flight,1";
  const std::string topic = "/k40t/raw/rx";
  int frames = 0;
  parser.feed(bytes.data(), bytes.size(), [&](const protocol::FrameView& view) {
    ++frames;
    out.write(ExportedFrame{bag, topic, 1700000000123456789, 7, view}, protocol::CodecOptions{});
  });
  EXPECT_EQ(frames, 1);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, separator);) cells.push_back(cell);
  return cells;
}

class FrameExportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/k40t_frame_export_XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string dir_;
};

TEST_F(FrameExportTest, CsvHasOneFilePerMessageWithTheHeaderAndTheFields) {
  Result<std::unique_ptr<FrameExport>> out = open_csv_export(dir_ + "/csv");
  ASSERT_TRUE(out) << out.error();
  export_frame(*out.value(), golden_attitude());
  ASSERT_TRUE(out.value()->finish().is_ok());

  std::stringstream text(read_text(dir_ + "/csv/0x000002_gimbal_attitude.csv"));
  std::string names, values, extra;
  ASSERT_TRUE(std::getline(text, names)) << "no 0x000002_gimbal_attitude.csv";
  ASSERT_TRUE(std::getline(text, values));
  EXPECT_FALSE(std::getline(text, extra)) << extra;
  // The bag's comma quotes its cell; the pod 03/01 -> host 01/01, SEQ 0x2B = 43 (3.1.1.2).
  EXPECT_EQ(
      values.rfind("\"flight,1\",/k40t/raw/rx,1700000000123456789,0x03/0x01,0x01/0x01,43,", 0), 0u)
      << values;
  const std::vector<std::string> columns = split(names, ',');
  ASSERT_GE(columns.size(), 6u);
  EXPECT_EQ(std::vector<std::string>(columns.begin(), columns.begin() + 6),
            (std::vector<std::string>{"bag", "topic", "stamp_ns", "src", "dst", "seq"}));
  // After the quoted bag, the cells line up with the names; the document's values, scaled.
  const std::vector<std::string> cells = split(values.substr(values.find("\",") + 2), ',');
  ASSERT_EQ(cells.size() + 1, columns.size()) << values;
  const std::map<std::string, double> expected{{"joint_yaw_deg", 12.34},   {"joint_roll_deg", -1.5},
                                               {"joint_pitch_deg", -45.0}, {"yaw_deg", 90.0},
                                               {"roll_deg", 0.01},         {"pitch_deg", -90.0},
                                               {"yaw_rate_deg_s", 10.5}};
  for (const auto& [name, value] : expected) {
    const auto column = std::find(columns.begin(), columns.end(), name);
    ASSERT_NE(column, columns.end()) << name << " not in " << names;
    EXPECT_NEAR(std::stod(cells[column - columns.begin() - 1]), value, 1e-9) << name;
  }
}

TEST_F(FrameExportTest, JsonLinesHaveTheBagTopicStampAndTheDecodedFrame) {
  const std::string path = dir_ + "/frames.jsonl";
  Result<std::unique_ptr<FrameExport>> out = open_jsonl_export(path);
  ASSERT_TRUE(out) << out.error();
  export_frame(*out.value(), golden_attitude());
  ASSERT_TRUE(out.value()->finish().is_ok());
  const std::string text = read_text(path);
  ASSERT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_EQ(text.rfind("{\"bag\":\"flight,1\",\"topic\":\"/k40t/raw/rx\","
                       "\"stamp_ns\":1700000000123456789,\"frame\":{",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("\"offset\":7"), std::string::npos) << text;
  EXPECT_NE(text.find("\"joint_pitch_deg\":-45"), std::string::npos) << text;
}

TEST_F(FrameExportTest, UnwritablePlacesAreNamed) {
  const Result<std::unique_ptr<FrameExport>> jsonl = open_jsonl_export(dir_ + "/no/such/x.jsonl");
  ASSERT_FALSE(jsonl);
  EXPECT_NE(jsonl.error().find(dir_ + "/no/such/x.jsonl"), std::string::npos) << jsonl.error();
  const Result<std::unique_ptr<FrameExport>> csv = open_csv_export(dir_ + "/no/such/dir");
  ASSERT_FALSE(csv);
  EXPECT_NE(csv.error().find("cannot create " + dir_ + "/no/such/dir"), std::string::npos)
      << csv.error();
}

}  // namespace
}  // namespace k40t::driver
