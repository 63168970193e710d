// Every golden frame in test/data/golden/*.txt (format: test/data/golden/README.md), written by
// hand from the document, against the parser, the catalogue's decoders and encode_args().
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "golden_checks.h"
#include "k40t_driver/protocol/catalogue.h"

namespace k40t::testing {
namespace {

// The checks of one frame; failures are reported with the frame's file and line.
void check_frame(const GoldenFrame& golden) {
  SCOPED_TRACE(golden.where());
  const protocol::CodecOptions codec;
  const SplitFrame split = split_frame(golden);
  ASSERT_TRUE(split.ok) << split.problem;

  const protocol::MessageInfo* info = protocol::find_message(split.header.message_id);
  ASSERT_NE(info, nullptr) << "the catalogue does not know "
                           << protocol::display_name(split.header.message_id);
  EXPECT_EQ(golden.name, info->name) << "the title comment names another message";
  EXPECT_EQ(golden.section, info->section) << "the title comment cites another section";
  expect_describes_to_expected(golden, codec);

  if (info->direction == protocol::Direction::kHostToPod) {
    Result<protocol::Payload> encoded = info->encode_args(golden.args(), codec);
    ASSERT_TRUE(encoded) << encoded.error();
    EXPECT_TRUE(same_bytes(std::vector<uint8_t>(encoded->data(), encoded->data() + encoded->size),
                           split.payload))
        << info->name
        << ": encode_args of the expected fields differs from the hand-written payload";
  }
}

TEST(GoldenFiles, EveryFrameParsesDecodesAndReencodes) {
  const std::vector<std::string> files = golden_file_paths();
  ASSERT_FALSE(files.empty()) << "no golden files in " << K40T_TEST_DATA_DIR "/golden";
  size_t frames = 0;
  for (const std::string& path : files) {
    Result<std::vector<GoldenFrame>> parsed = read_golden_file(path);
    ASSERT_TRUE(parsed) << "malformed golden file: " << parsed.error();
    for (const GoldenFrame& golden : parsed.value()) check_frame(golden);
    frames += parsed->size();
  }
  RecordProperty("golden_frames", static_cast<int>(frames));
}

TEST(GoldenFileReader, ReadsFramesOverSeveralLines) {
  Result<std::vector<GoldenFrame>> frames = parse_golden_text(
      "# comment\n\n# 3.2.5.1 laser_range: title\n# more\nFD 02\n04 01\n= a=1 b=\"two words\"\n"
      "# next\nFD\n=\n",
      "t.txt");
  ASSERT_TRUE(frames) << frames.error();
  ASSERT_EQ(frames->size(), 2u);
  EXPECT_EQ(frames->at(0).bytes, (std::vector<uint8_t>{0xFD, 0x02, 0x04, 0x01}));
  EXPECT_EQ(frames->at(0).where(), "t.txt:5");
  EXPECT_EQ(frames->at(0).section, "3.2.5.1");
  EXPECT_EQ(frames->at(0).name, "laser_range");
  EXPECT_EQ(frames->at(1).name, "");  // no title comment
  EXPECT_EQ(frames->at(0).expected,
            (FieldValues{{"a", "1"}, {"b", "two words"}}));  // in the line's order
  EXPECT_TRUE(frames->at(1).expected.empty());
}

TEST(GoldenFileReader, MalformedFilesFailWithFileAndLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"FD 02\n", "t.txt:1: the frame starting at t.txt:1 has no '=' line"},
      {"= a=1\n", "t.txt:1: '=' line without"},
      {"FD 0G\n= a=1\n", "t.txt:1: '0G' is not a hex byte"},
      {"FD 002\n= a=1\n", "'002' is not a hex byte"},
      {"FD\n= a\n", "t.txt:2: expected name=value"},
      {"FD\n= a=1 a=2\n", "given twice"},
      {"FD\n= a=\"open\n", "unterminated quote"},
      {"# 3.1.1.1 a: x\nFD\n# 3.1.1.2 b: y\nFD\n=\n",
       "t.txt:3: the frame starting at t.txt:2 has no '=' line"},
      {"# only comments\n", "no frames"},
  };
  for (const auto& [text, expected] : cases) {
    Result<std::vector<GoldenFrame>> frames = parse_golden_text(text, "t.txt");
    ASSERT_FALSE(frames) << text;
    EXPECT_NE(frames.error().find(expected), std::string::npos) << frames.error();
  }
}

TEST(GoldenFileReader, FieldComparisonNamesTheMismatch) {
  FieldRecorder fields;
  fields.real("distance_m", 12.3);
  fields.enumeration("code", 8, "busy (repeated request)");
  fields.bytes("ip", std::vector<uint8_t>{192, 168, 144, 64}.data(), 4);
  fields.boolean("on", true);
  fields.text("name", "img_0001");
  EXPECT_EQ(field_differences({{"distance_m", "12.3"},
                               {"code", "8"},
                               {"ip", "192.168.144.64"},
                               {"on", "1"},
                               {"name", "img_0001"}},
                              fields),
            "");
  EXPECT_EQ(value_difference(fields.fields()[1], "Busy_Repeated_Request"), "");
  EXPECT_EQ(value_difference(fields.fields()[3], "true"), "");
  EXPECT_EQ(value_difference(fields.fields()[0], "12.4"),
            "field 'distance_m': expected 12.4, got 12.300000000000001");
  EXPECT_EQ(value_difference(fields.fields()[1], "0"),
            "field 'code': expected 0, got 8 (busy (repeated request))");
  EXPECT_EQ(value_difference(fields.fields()[2], "192.168.144.65"),
            "field 'ip': expected 192.168.144.65, got 192,168,144,64");
  EXPECT_EQ(value_difference(fields.fields()[3], "0"), "field 'on': expected 0, got 1");
  EXPECT_EQ(value_difference(fields.fields()[4], "img_0002"),
            "field 'name': expected img_0002, got \"img_0001\"");

  // A list of fields: missing, extra and misordered fields are named too.
  FieldRecorder two;
  two.integer("a", -1);
  two.unsigned_integer("b", 2);
  EXPECT_EQ(field_differences({{"a", "-1"}, {"b", "2"}}, two), "");
  EXPECT_EQ(field_differences({{"a", "-1"}}, two),
            "  field 'b' = 2 is not expected (only 1 fields are)\n");
  EXPECT_EQ(field_differences({{"a", "-1"}, {"b", "2"}, {"c", "3"}}, two),
            "  field 'c': expected 3, but the message has no field #2\n");
  EXPECT_EQ(field_differences({{"b", "2"}, {"a", "-1"}}, two),
            "  field #0 is 'a', expected 'b' (fields in wire order)\n"
            "  field #1 is 'b', expected 'a' (fields in wire order)\n");
  EXPECT_EQ(field_differences({{"a", "-2"}, {"b", "2"}}, two),
            "  field 'a': expected -2, got -1\n");
}

}  // namespace
}  // namespace k40t::testing
