// Every golden frame in test/data/golden/*.txt (format: test/data/golden/README.md), written by
// hand from the document, against the parser, the catalogue's decoders and encode_args().
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "golden_frames.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::test {
namespace {

std::vector<std::string> golden_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(K40T_TEST_DATA_DIR "/golden")) {
    if (entry.path().extension() == ".txt") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The checks of one frame; failures are reported with the frame's file and line.
void check_frame(const GoldenFrame& golden) {
  SCOPED_TRACE(golden.where);
  const protocol::CodecOptions codec;
  protocol::FrameParser parser(protocol::CrcCoverage::kHeaderExcluded);
  std::vector<protocol::FrameHeader> headers;
  std::vector<std::vector<uint8_t>> payloads;
  parser.feed(golden.bytes.data(), golden.bytes.size(), [&](const protocol::FrameView& f) {
    headers.push_back(f.header);
    payloads.emplace_back(f.payload, f.payload + f.payload_size);
  });
  ASSERT_EQ(headers.size(), 1u) << "the bytes must hold exactly one frame (checksum errors: "
                                << parser.stats().checksum_errors << ")";
  EXPECT_EQ(parser.stats().bytes_discarded, 0u);
  EXPECT_EQ(protocol::kFrameOverhead + payloads[0].size(), golden.bytes.size())
      << "bytes after the frame";

  const protocol::MessageInfo* info = protocol::find_message(headers[0].message_id);
  ASSERT_NE(info, nullptr) << "the catalogue does not know "
                           << protocol::display_name(headers[0].message_id);
  DecodedFields decoded;
  const Status described = info->describe(payloads[0].data(), payloads[0].size(), codec, decoded);
  ASSERT_TRUE(described) << described.message();
  for (const auto& [name, value] : golden.expected) {
    const Status match = decoded.matches(name, value);
    EXPECT_TRUE(match) << info->name << ": " << match.message();
  }

  if (info->direction == protocol::Direction::kHostToPod) {
    Result<protocol::Payload> encoded = info->encode_args(golden.expected, codec);
    ASSERT_TRUE(encoded) << encoded.error();
    EXPECT_EQ(std::vector<uint8_t>(encoded->data(), encoded->data() + encoded->size), payloads[0])
        << info->name
        << ": encode_args of the expected fields differs from the hand-written payload";
  }
}

TEST(GoldenFiles, EveryFrameParsesDecodesAndReencodes) {
  const std::vector<std::string> files = golden_files();
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
      "# comment\n\nFD 02\n04 01\n= a=1 b=\"two words\"\n# next\nFD\n=\n", "t.txt");
  ASSERT_TRUE(frames) << frames.error();
  ASSERT_EQ(frames->size(), 2u);
  EXPECT_EQ(frames->at(0).bytes, (std::vector<uint8_t>{0xFD, 0x02, 0x04, 0x01}));
  EXPECT_EQ(frames->at(0).where, "t.txt:3");
  EXPECT_EQ(frames->at(0).expected.at("b"), "two words");
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
      {"# only comments\n", "no frames"},
  };
  for (const auto& [text, expected] : cases) {
    Result<std::vector<GoldenFrame>> frames = parse_golden_text(text, "t.txt");
    ASSERT_FALSE(frames) << text;
    EXPECT_NE(frames.error().find(expected), std::string::npos) << frames.error();
  }
}

TEST(GoldenFileReader, FieldComparisonNamesTheMismatch) {
  DecodedFields fields;
  fields.real("distance_m", 12.3);
  fields.enumeration("code", 8, "busy (repeated request)");
  fields.bytes("ip", std::vector<uint8_t>{192, 168, 144, 64}.data(), 4);
  EXPECT_TRUE(fields.matches("distance_m", "12.3"));
  EXPECT_TRUE(fields.matches("code", "8"));
  EXPECT_TRUE(fields.matches("code", "Busy_Repeated_Request"));
  EXPECT_TRUE(fields.matches("ip", "192.168.144.64"));
  EXPECT_EQ(fields.matches("distance_m", "12.4").message(),
            "field 'distance_m': expected 12.4, decoded 12.300000000000001");
  EXPECT_FALSE(fields.matches("code", "0"));
  EXPECT_FALSE(fields.matches("ip", "192.168.144.65"));
  EXPECT_NE(fields.matches("range_m", "1").message().find("its fields: distance_m, code, ip"),
            std::string::npos);
}

}  // namespace
}  // namespace k40t::test
