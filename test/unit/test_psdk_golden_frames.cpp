// Whole PSDK frames written by hand from the protocol document (test/data/psdk_golden/*.txt:
// header, CRC16, DATA, CRC32, some AES-encrypted), one or more for every command and push the
// SKYPORT bridge handles and every ACK it sends. For each frame:
//   1. the parser takes the bytes as exactly one good frame, nothing left over, no error counted;
//   2. the catalogue knows the frame's (set, id, packet type) under the title's name;
//   3. DATA (decrypted with the golden credentials) decodes to the '=' line's fields;
//   4. the codec encodes the decoded DATA back to the same bytes, and the frame layer the header
//      and DATA back to the same frame (CRCs, padding and ciphertext included).
// Frames in the layouts of DJI's headers (docs/psdk.md P30, P31) are named as below and go through
// header_variants.h's codecs instead of the catalogue's.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "field_recorder.h"
#include "golden_file.h"
#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/psdk/catalogue.h"
#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/psdk/commands/header_variants.h"
#include "k40t_driver/psdk/parser.h"
#include "psdk_golden_frames.h"

namespace k40t::psdk {
namespace {

using testing::FieldRecorder;
using testing::GoldenFrame;

Aes128Ecb golden_cipher() {
  return Aes128Ecb(derive_aes_key(
      {"k40t_test", "123456", "0123456789abcdef0123456789abcdef", "dev@example.com"}));
}

// A layout variant: its key, how to describe its DATA, and its DATA encoded again.
struct Variant {
  CommandKey key;
  PacketType packet;
  std::function<Status(const Data&, FieldRecorder&)> describe;
  std::function<Result<Data>(const Data&)> reencode;
};

const std::map<std::string, Variant>& variants() {
  static const std::map<std::string, Variant> all = {
      // P30: 3.4.5 with a uint16 interval (5 bytes).
      {"set_shoot_photo_mode_u16",
       {SetShootPhotoMode::key(), PacketType::kCommand,
        [](const Data& d, FieldRecorder& sink) {
          const Result<ShootPhotoModeWide> m = decode_shoot_photo_mode(d.data(), d.size);
          if (m) ShootPhotoModeWide::layout(m.value(), LayoutSink(sink));
          return m.status();
        },
        [](const Data& d) -> Result<Data> {
          const Result<ShootPhotoModeWide> m = decode_shoot_photo_mode(d.data(), d.size);
          if (!m) return m.status();
          // The set command's DATA is the ACK's without the return code.
          Result<Data> ack = encode_shoot_photo_mode_ack(m.value(), PsdkLayout::kDjiHeaders);
          if (!ack) return ack;
          Data out;
          out.size = ack->size - 1;
          std::copy(ack->data() + 1, ack->data() + ack->size, out.bytes.begin());
          return out;
        }}},
      // P30: 3.4.6's ACK with a uint16 interval (6 bytes).
      {"get_shoot_photo_mode_ack_u16",
       {GetShootPhotoMode::key(), PacketType::kAck,
        [](const Data& d, FieldRecorder& sink) {
          return describe_data<ShootPhotoModeWideAck>(d.data(), d.size, sink);
        },
        [](const Data& d) -> Result<Data> {
          const Result<ShootPhotoModeWideAck> m =
              decode_data<ShootPhotoModeWideAck>(d.data(), d.size);
          if (!m) return m.status();
          return encode_shoot_photo_mode_ack(m.value(), PsdkLayout::kDjiHeaders);
        }}},
      // P31: 3.3.1 without the OSDK fields (33 bytes); they read 0 and encode as 0.
      {"link_bandwidth_push_33",
       {LinkBandwidthPush::key(), PacketType::kCommand,
        [](const Data& d, FieldRecorder& sink) {
          bool has_osdk = true;
          const Result<LinkBandwidthPush> p = decode_link_bandwidth(d.data(), d.size, &has_osdk);
          if (p) describe(p.value(), sink);
          if (p && has_osdk) return Status::fail("read as the 42-byte layout");
          return p.status();
        },
        [](const Data& d) -> Result<Data> {
          bool has_osdk = true;
          const Result<LinkBandwidthPush> p = decode_link_bandwidth(d.data(), d.size, &has_osdk);
          if (!p) return p.status();
          Result<Data> full = encode_data(p.value());
          if (!full) return full;
          for (size_t i = kLinkBandwidthShortSize; i < full->size; ++i) {
            if (full->bytes[i] != 0) return Status::fail("an OSDK field is not 0");
          }
          full->size = kLinkBandwidthShortSize;
          return full;
        }}},
  };
  return all;
}

std::vector<uint8_t> as_bytes(const uint8_t* data, size_t size) {
  return std::vector<uint8_t>(data, data + size);
}

void check_frame(const GoldenFrame& golden) {
  SCOPED_TRACE(golden.where() + " " + golden.name);
  FrameParser parser;
  std::vector<FrameView> frames;
  std::vector<std::vector<uint8_t>> frame_bytes;
  std::vector<Data> plain;
  const Aes128Ecb cipher = golden_cipher();
  parser.feed(golden.bytes.data(), golden.bytes.size(), [&](const FrameView& f) {
    frames.push_back(f);
    frame_bytes.push_back(as_bytes(f.bytes, f.size));
    const Result<Data> d = open_data(f, &cipher);
    EXPECT_TRUE(d) << d.error();
    plain.push_back(d ? d.value() : Data{});
  });
  ASSERT_EQ(frames.size(), 1u) << "the bytes are not exactly one good frame";
  EXPECT_EQ(frame_bytes[0], golden.bytes) << "bytes left over";
  EXPECT_EQ(parser.stats().bytes_discarded, 0u);
  const FrameHeader& h = frames[0].header;
  const Data& data = plain[0];

  FieldRecorder fields;
  Result<Data> again = Status::fail("no codec");
  const auto variant = variants().find(golden.name);
  if (variant != variants().end()) {
    EXPECT_EQ(h.command, variant->second.key);
    EXPECT_EQ(h.packet_type, variant->second.packet);
    const Status described = variant->second.describe(data, fields);
    ASSERT_TRUE(described) << described.message();
    again = variant->second.reencode(data);
  } else {
    const CommandInfo* info = find_command(h.command, h.packet_type);
    ASSERT_NE(info, nullptr) << "not in the catalogue";
    EXPECT_EQ(info->name, golden.name) << "the header's command is another one";
    const Status described = info->describe(data.data(), data.size, fields);
    ASSERT_TRUE(described) << described.message();
    again = info->reencode(data.data(), data.size);
  }
  EXPECT_EQ(testing::field_differences(golden.expected, fields), "");
  ASSERT_TRUE(again) << again.error();
  EXPECT_EQ(as_bytes(again->data(), again->size), as_bytes(data.data(), data.size))
      << "the encoder does not give back the DATA written by hand";

  const Result<EncodedFrame> frame = encode_frame(h, data.data(), data.size, &cipher);
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(as_bytes(frame->data(), frame->size()), golden.bytes)
      << "the frame layer does not give back the frame written by hand";
}

// Every frame of every PSDK golden file; a file that cannot be read fails the test.
std::vector<GoldenFrame> all_golden_frames() {
  std::vector<GoldenFrame> all;
  for (const std::string& path : test::psdk_golden_paths()) {
    const Result<std::vector<GoldenFrame>> frames = testing::read_golden_file(path);
    EXPECT_TRUE(frames) << frames.error();
    if (frames) all.insert(all.end(), frames->begin(), frames->end());
  }
  return all;
}

TEST(PsdkGoldenFrames, EveryFrameDecodesAndEncodesBackByteForByte) {
  const std::vector<GoldenFrame> frames = all_golden_frames();
  for (const GoldenFrame& frame : frames) {
    EXPECT_FALSE(frame.name.empty()) << frame.where() << ": no title '# <section> <name>:'";
    check_frame(frame);
  }
  EXPECT_GT(frames.size(), 0u);
}

TEST(PsdkGoldenFrames, SomeFramesAreEncrypted) {
  size_t encrypted = 0;
  for (const GoldenFrame& frame : all_golden_frames()) {
    if (frame.bytes.size() > 4 && frame.bytes[4] >> 5 == 1) ++encrypted;
  }
  EXPECT_GE(encrypted, 2u) << "an encrypted command and an encrypted ACK at least";
}

}  // namespace
}  // namespace k40t::psdk
