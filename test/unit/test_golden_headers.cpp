// Every hand-written frame of test/data/golden/*.txt (see golden_file.h for the format): the
// parser accepts it as one good frame with header_excluded coverage, the catalogue knows its id
// under the name and section the entry gives, the addresses fit the message's direction, and the
// catalogue's decoder reports exactly the fields of the '=' line.
#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "field_recorder.h"
#include "golden_entry_reader.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::protocol {
namespace {

using testing::FieldRecorder;
using testing::GoldenFrame;

const std::string kGoldenDir = std::string(K40T_TEST_DATA_DIR) + "/golden";

std::vector<std::string> golden_files() {
  std::vector<std::string> files;
  if (DIR* dir = opendir(kGoldenDir.c_str())) {
    while (const dirent* e = readdir(dir)) {
      const std::string name = e->d_name;
      if (name.size() > 4 && name.compare(name.size() - 4, 4, ".txt") == 0)
        files.push_back(kGoldenDir + "/" + name);
    }
    closedir(dir);
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<GoldenFrame> all_golden_frames() {
  std::vector<GoldenFrame> all;
  for (const std::string& file : golden_files()) {
    std::string error;
    std::vector<GoldenFrame> frames = testing::load_golden_file(file, &error);
    EXPECT_EQ(error, "");
    all.insert(all.end(), frames.begin(), frames.end());
  }
  return all;
}

// The one good frame `bytes` parse to (header_excluded coverage), or a failure.
::testing::AssertionResult parses_as_one_frame(const std::vector<uint8_t>& bytes,
                                               FrameHeader* header, std::vector<uint8_t>* payload) {
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  int count = 0;
  parser.feed(bytes.data(), bytes.size(), [&](const FrameView& f) {
    ++count;
    *header = f.header;
    payload->assign(f.payload, f.payload + f.payload_size);
  });
  if (count != 1 || parser.stats().bytes_discarded != 0 || parser.stats().checksum_errors != 0) {
    return ::testing::AssertionFailure()
           << count << " frames, " << parser.stats().checksum_errors << " checksum errors, "
           << parser.stats().bytes_discarded << " bytes discarded";
  }
  return ::testing::AssertionSuccess();
}

TEST(GoldenFiles, EveryEntryDecodesToItsExpectedFields) {
  const std::vector<GoldenFrame> frames = all_golden_frames();
  ASSERT_FALSE(frames.empty()) << "no golden frames under " << kGoldenDir;
  for (const GoldenFrame& g : frames) {
    SCOPED_TRACE(g.where());
    FrameHeader header;
    std::vector<uint8_t> payload;
    ASSERT_TRUE(parses_as_one_frame(g.bytes, &header, &payload));

    const MessageInfo* info = find_message(header.message_id);
    ASSERT_NE(info, nullptr) << "id 0x" << std::hex << header.message_id
                             << " is not in the catalogue";
    EXPECT_EQ(g.name, info->name);
    EXPECT_EQ(g.section, info->section);
    // The host's end of a message is the host itself, or the flight controller it stands in for
    // (0x000310 / 0x000320, section 3.2.4.15 and 3.2.4.24).
    const Address host_end =
        info->direction == Direction::kHostToPod ? header.source : header.destination;
    EXPECT_TRUE(host_end == kHostAddress || host_end == kFlightControllerAddress)
        << "a " << to_string(info->direction) << " message has the host (or flight controller) at "
        << (info->direction == Direction::kHostToPod ? "its source" : "its destination");

    FieldRecorder recorder;
    const Status described =
        info->describe(payload.data(), payload.size(), CodecOptions{}, recorder);
    ASSERT_TRUE(described) << described.message();
    EXPECT_EQ(testing::field_differences(g.expected, recorder.fields()), "");
  }
}

// A family's golden file must hold a frame for each of its catalogue ids (the generated plain ACK
// entries excepted: one of them per file is enough).
void expect_file_covers(const std::string& file, bool (*in_family)(MessageId)) {
  std::string error;
  const std::vector<GoldenFrame> frames =
      testing::load_golden_file(kGoldenDir + "/" + file, &error);
  ASSERT_EQ(error, "");
  std::set<std::string> names;
  bool has_plain_ack = false;
  for (const GoldenFrame& g : frames) {
    names.insert(g.name);
    const MessageInfo* info = find_message(g.name);
    has_plain_ack |= info != nullptr && info->describe == &describe_payload<PlainAck>;
  }
  EXPECT_TRUE(has_plain_ack) << file << " has no plain ACK frame";
  for (const MessageInfo& m : catalogue()) {
    if (!in_family(m.id) || m.describe == &describe_payload<PlainAck>) continue;
    EXPECT_EQ(names.count(m.name), 1u) << file << " has no frame for " << m.name;
  }
}

TEST(GoldenFiles, GimbalLaserSbusFileCoversEveryMessageOfItsFamilies) {
  expect_file_covers("gimbal_laser_sbus.txt", [](MessageId id) {
    const MessageId request = request_id_of(id);
    const bool gimbal_report = request == 0x000001 || request == 0x000002;  // 0x03..0x0F: camera's
    const bool gimbal_request = request >= 0x000010 && request <= 0x0000FF;
    const bool laser_or_sbus = request >= 0x000400 && request <= 0x0005FF;
    return gimbal_report || gimbal_request || laser_or_sbus;
  });
}

}  // namespace
}  // namespace k40t::protocol
