// PSDK frame layout (protocol document 2.1, docs/psdk.md#frames). The golden frames are
// docs/psdk.md#frames' whole-frame vectors, and one encrypted frame written by hand: header bytes
// from 2.1, the key MD5("K40T bridge" "123456" "0123456789abcdef0123456789abcdef"
// "dev@example.com") computed with Python's hashlib, the ciphertext with `openssl enc -aes-128-ecb
// -nopad`, the CRCs with test/data/psdk_frame_crc.py.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/psdk/frame.h"
#include "psdk_test_support.h"

namespace k40t::psdk {
namespace {

std::vector<uint8_t> bytes_of(const EncodedFrame& f) {
  return {f.data(), f.data() + f.size()};
}

using testing::kGetVersion;  // docs/psdk.md#frames' whole-frame vectors
using testing::kGetVersionAck;

// 3.2.3 floating-window message "SD full" + NUL, seq 5, no ACK, AES (ENC 1 in bits 5-7 of byte 4)
// with 8 bytes of padding: byte 4 = 0x28; 32 bytes in all.
const std::vector<uint8_t> kEncryptedFloatingWindow = {
    0xaa, 0x20, 0x00, 0x00, 0x28, 0x00, 0x02, 0x03, 0x05, 0x00, 0x12, 0xf9, 0xc1, 0xbe, 0xb4, 0xb0,
    0xaf, 0x0e, 0xcf, 0xab, 0x4a, 0x5b, 0x7e, 0x7f, 0x8f, 0x36, 0x74, 0x75, 0xdc, 0xb8, 0xb6, 0x18};

Credentials test_credentials() {
  return {"K40T bridge", "123456", "0123456789abcdef0123456789abcdef", "dev@example.com"};
}

// A header that asks for AES encryption (ENC 1).
FrameHeader aes_header() {
  FrameHeader h;
  h.encryption = Encryption::kAes;
  return h;
}

// The result is an error whose message contains `words`.
template <class T>
::testing::AssertionResult refused_naming(const Result<T>& result, const std::string& words) {
  if (result)
    return ::testing::AssertionFailure() << "accepted, expected an error naming " << words;
  if (result.error().find(words) == std::string::npos)
    return ::testing::AssertionFailure()
           << "the error does not name " << words << ": " << result.error();
  return ::testing::AssertionSuccess();
}

FrameHeader get_version_header() {
  FrameHeader h;
  h.ack_request = AckRequest::kAfterExecution;
  h.command = key_of(CommandSet::kPayloadState, 0x02);
  return h;
}

TEST(PsdkFrame, EncodesTheGetVersionVector) {
  auto frame = encode_frame(get_version_header(), nullptr, 0);
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(bytes_of(frame.value()), kGetVersion);
}

TEST(PsdkFrame, EncodesTheGetVersionAckVector) {
  FrameHeader h;
  h.packet_type = PacketType::kAck;
  h.command = key_of(CommandSet::kPayloadState, 0x02);
  const uint8_t data[] = {0x00, 0x00, 0x00, 0x03, 0x01};
  auto frame = encode_frame(h, data, sizeof(data));
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(bytes_of(frame.value()), kGetVersionAck);
}

TEST(PsdkFrame, ParsesHeaderFields) {
  const FrameHeader h = parse_header(kGetVersionAck.data());
  EXPECT_EQ(frame_length_field(kGetVersionAck.data()), 21u);
  EXPECT_EQ(frame_version_field(kGetVersionAck.data()), 0);
  EXPECT_EQ(h.packet_type, PacketType::kAck);
  EXPECT_EQ(h.ack_request, AckRequest::kNoAck);
  EXPECT_EQ(h.encryption, Encryption::kNone);
  EXPECT_EQ(h.command, key_of(CommandSet::kPayloadState, 0x02));
  EXPECT_EQ(h.sequence, 0);
}

TEST(PsdkFrame, SequenceIsLittleEndian) {
  FrameHeader h = get_version_header();
  h.sequence = 0x1234;
  auto frame = encode_frame(h, nullptr, 0);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->data()[8], 0x34);
  EXPECT_EQ(frame->data()[9], 0x12);
  EXPECT_EQ(parse_header(frame->data()).sequence, 0x1234);
}

TEST(PsdkFrame, EncodesTheEncryptedVector) {
  const Aes128Ecb cipher(derive_aes_key(test_credentials()));
  FrameHeader h = aes_header();
  h.command = key_of(CommandSet::kAppFunction, 0x03);
  h.sequence = 5;
  const uint8_t text[] = {'S', 'D', ' ', 'f', 'u', 'l', 'l', 0};
  auto frame = encode_frame(h, text, sizeof(text), &cipher);
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(bytes_of(frame.value()), kEncryptedFloatingWindow);
}

TEST(PsdkFrame, OpensTheEncryptedVector) {
  const Aes128Ecb cipher(derive_aes_key(test_credentials()));
  FrameView view;
  view.header = parse_header(kEncryptedFloatingWindow.data());
  view.data = kEncryptedFloatingWindow.data() + kHeaderSize;
  view.data_size = kEncryptedFloatingWindow.size() - kFrameOverhead;
  EXPECT_EQ(view.header.padding, 8);
  EXPECT_EQ(view.header.encryption, Encryption::kAes);
  auto data = open_data(view, &cipher);
  ASSERT_TRUE(data) << data.error();
  EXPECT_EQ(std::vector<uint8_t>(data->data(), data->data() + data->size),
            (std::vector<uint8_t>{'S', 'D', ' ', 'f', 'u', 'l', 'l', 0}));
}

TEST(PsdkFrame, EncryptedFrameWithoutKeyFailsClearly) {
  FrameView view;
  view.header = parse_header(kEncryptedFloatingWindow.data());
  view.data = kEncryptedFloatingWindow.data() + kHeaderSize;
  view.data_size = 16;
  auto data = open_data(view, nullptr);
  EXPECT_TRUE(refused_naming(data, "no AES key"));

  FrameHeader h = view.header;
  auto frame = encode_frame(h, view.data, 8, nullptr);
  EXPECT_TRUE(refused_naming(frame, "no AES key"));
}

TEST(PsdkFrame, EncryptionPadsToWholeBlocks) {
  const Aes128Ecb cipher(derive_aes_key(test_credentials()));
  FrameHeader h = aes_header();
  const std::vector<uint8_t> data(kMaxDataSize, 0x5A);
  for (size_t size : {size_t{0}, size_t{1}, size_t{15}, size_t{16}, size_t{17}, size_t{40},
                      size_t{241}, size_t{256}}) {
    auto frame = encode_frame(h, data.data(), size, &cipher);
    ASSERT_TRUE(frame) << frame.error();
    const size_t padded = (size + 15) / 16 * 16;
    EXPECT_EQ(frame->size(), kFrameOverhead + padded) << size;
    EXPECT_EQ(parse_header(frame->data()).padding, padded - size) << size;
  }
}

TEST(PsdkFrame, EncryptedRoundTripForEveryDataSize) {
  const Aes128Ecb cipher(derive_aes_key(test_credentials()));
  FrameHeader h = aes_header();
  h.command = key_of(CommandSet::kOsdkFunction, 0x02);
  std::vector<uint8_t> data(kMaxDataSize);
  for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<uint8_t>(i * 13 + 1);
  for (size_t size = 0; size <= kMaxDataSize; ++size) {
    auto frame = encode_frame(h, data.data(), size, &cipher);
    ASSERT_TRUE(frame) << size << ": " << frame.error();
    FrameView view;
    view.header = parse_header(frame->data());
    view.data = frame->data() + kHeaderSize;
    view.data_size = frame->size() - kFrameOverhead;
    EXPECT_EQ(view.data_size % 16, 0u) << size;
    if (size > 0) {
      EXPECT_NE(std::vector<uint8_t>(view.data, view.data + size),
                std::vector<uint8_t>(data.begin(), data.begin() + size))
          << "DATA of " << size << " bytes left in clear";
    }
    auto opened = open_data(view, &cipher);
    ASSERT_TRUE(opened) << size << ": " << opened.error();
    EXPECT_EQ(std::vector<uint8_t>(opened->data(), opened->data() + opened->size),
              std::vector<uint8_t>(data.begin(), data.begin() + size))
        << size;
  }
}

TEST(PsdkFrame, AcceptsTheLargestFrame) {
  std::vector<uint8_t> data(kMaxDataSize, 0x11);
  auto frame = encode_frame(FrameHeader{}, data.data(), data.size());
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(frame->size(), 272u);
  EXPECT_EQ(frame_length_field(frame->data()), 272u);
}

TEST(PsdkFrame, RejectsDataOver256Bytes) {
  std::vector<uint8_t> data(kMaxDataSize + 1, 0x11);
  auto frame = encode_frame(FrameHeader{}, data.data(), data.size());
  EXPECT_TRUE(refused_naming(frame, "256"));
}

TEST(PsdkFrame, RejectsDataThatPaddingPushesOver256Bytes) {
  const Aes128Ecb cipher(derive_aes_key(test_credentials()));
  FrameHeader h = aes_header();
  std::vector<uint8_t> data(250, 0x11);  // 250 + 6 = 256 fits
  EXPECT_TRUE(encode_frame(h, data.data(), data.size(), &cipher));
  data.resize(257);
  auto frame = encode_frame(h, data.data(), data.size(), &cipher);
  EXPECT_TRUE(refused_naming(frame, "256"));
}

TEST(PsdkFrame, RejectsUndefinedEncryptionAndOversizedAckRequest) {
  FrameHeader h;
  h.encryption = static_cast<Encryption>(2);
  auto frame = encode_frame(h, nullptr, 0);
  EXPECT_TRUE(refused_naming(frame, "encryption"));
  h = FrameHeader{};
  h.ack_request = static_cast<AckRequest>(0x20);
  frame = encode_frame(h, nullptr, 0);
  EXPECT_TRUE(refused_naming(frame, "5 bits"));
}

TEST(PsdkFrame, OpenDataRejectsPaddingLongerThanData) {
  FrameView view;
  const uint8_t data[4] = {1, 2, 3, 4};
  view.header.padding = 5;
  view.data = data;
  view.data_size = 4;
  auto opened = open_data(view);
  EXPECT_TRUE(refused_naming(opened, "padding"));
}

}  // namespace
}  // namespace k40t::psdk
