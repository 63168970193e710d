// Round trips, validation and decode edge cases of the common camera family (document sections
// 3.2.1.1, 3.2.1.4, 3.2.4). The byte-exact checks against the document are in
// test_camera_golden.cpp; here every struct is encoded and decoded with values other than its
// defaults, every validated field is pushed out of its range, and the text fields are tried at
// their exact width and one byte over.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "camera_message_samples.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "message_checks.h"

namespace k40t::protocol {
namespace {

using camera_samples::sample;

// ---- round trips --------------------------------------------------------------------------------
template <class T>
void expect_round_trip(const CodecOptions& options) {
  testing::expect_round_trip(sample<T>(), options);
}

// Every struct of the family's list (camera.h): a new struct without a sample does not compile.
void round_trip_every_struct(const CodecOptions& options) {
  for_each_message(CameraMessages{}, [&](auto* type) {
    expect_round_trip<std::remove_pointer_t<decltype(type)>>(options);
  });
}

TEST(CameraMessages, EveryStructRoundTripsWithBigEndianAcks) {
  round_trip_every_struct({});
}

TEST(CameraMessages, EveryStructRoundTripsWithLittleEndianAcks) {
  CodecOptions little;
  little.ack_byte_order = ByteOrder::kLittle;
  round_trip_every_struct(little);
}

// ---- text fields: exactly the width, and one byte over
// -------------------------------------------
template <class T>
void expect_text_widths() {
  SCOPED_TRACE(T::kName);
  T m = sample<T>();
  m.folder = std::string(kCameraFolderBytes, 'F');
  m.name = std::string(kCameraFileNameBytes, 'N');
  Result<Payload> full = encode_payload(m);
  ASSERT_TRUE(full) << full.error();
  ASSERT_EQ(full->size, T::kSize);
  // Both texts fill their fields completely: no terminator, the name ends the payload.
  const size_t folder_at = T::kSize - kCameraFileNameBytes - kCameraFolderBytes;
  EXPECT_EQ(std::string(full->bytes.begin() + folder_at, full->bytes.begin() + folder_at + 20),
            m.folder);
  EXPECT_EQ(std::string(full->bytes.begin() + folder_at + 20, full->bytes.begin() + T::kSize),
            m.name);
  Result<T> back = decode_payload<T>(full->data(), full->size);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->folder, m.folder);
  EXPECT_EQ(back->name, m.name);

  T long_folder = m;
  long_folder.folder += 'F';
  EXPECT_EQ(encode_payload(long_folder).error(),
            std::string(T::kName) + ": field 'folder' must be at most 20 bytes, got 21");
  T long_name = m;
  long_name.name += 'N';
  EXPECT_EQ(encode_payload(long_name).error(),
            std::string(T::kName) + ": field 'name' must be at most 32 bytes, got 33");
  T with_nul = m;
  with_nul.name = std::string("a\0b", 3);
  EXPECT_NE(encode_payload(with_nul).error().find("'name' must not contain NUL"),
            std::string::npos);
}

TEST(CameraMessages, TextFieldsTakeExactly20And32BytesAndNoMore) {
  expect_text_widths<TakePhotoRequest>();
  expect_text_widths<RecordRequest>();
  expect_text_widths<PreciseReshootRequest>();
}

TEST(CameraMessages, ShortTextsArePaddedWithZeros) {
  TakePhotoRequest m;
  m.folder = "ab";
  Result<Payload> p = encode_payload(m);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->bytes[2], 'a');
  EXPECT_EQ(p->bytes[3], 'b');
  for (size_t i = 4; i < TakePhotoRequest::kSize; ++i) EXPECT_EQ(p->bytes[i], 0) << i;
}

// ---- decoding ----------------------------------------------------------------------------------
TEST(CameraMessages, ShortPayloadsAreRefusedWithTheSizes) {
  const std::vector<uint8_t> bytes(53, 0);
  EXPECT_EQ(decode_payload<TakePhotoRequest>(bytes.data(), bytes.size()).error(),
            "take_photo (0x000302): payload of 53 bytes is too short, need 54");
  EXPECT_FALSE(decode_payload<CameraSystemStatus>(bytes.data(), 14));
  EXPECT_FALSE(decode_payload<TargetGpsRequest>(bytes.data(), 41));
  // A data ACK that is longer than the code but shorter than its data is truncated, not a refusal.
  EXPECT_FALSE(decode_payload<GetIpAck>(bytes.data(), 7));
  EXPECT_FALSE(decode_payload<CameraGpsAck>(bytes.data(), 24));
}

TEST(CameraMessages, TrailingReservedBytesAreOptionalOnReceive) {
  const uint8_t report[15] = {0, 0, 0, 0, 1, 0, 5, 3,
                              0, 1, 0, 1, 0, 0, 0};  // 0x000003 without byte 16
  Result<CameraSystemStatus> status = decode_payload<CameraSystemStatus>(report, sizeof(report));
  ASSERT_TRUE(status) << status.error();
  EXPECT_DOUBLE_EQ(status->sd_total_mb, 10.0);
  const uint8_t photo[4] = {1, 2, 0x10, 0x00};  // 0x020302 without its 3 reserved bytes
  Result<PhotoStatus> frame = decode_payload<PhotoStatus>(photo, sizeof(photo));
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(frame->burst_count, 16);
}

TEST(CameraMessages, UndefinedCodesFromThePodAreReportedNotRefused) {
  const uint8_t payload[7] = {9, 99, 0, 0, 0, 0, 0};
  Result<PhotoStatus> status = decode_payload<PhotoStatus>(payload, sizeof(payload));
  ASSERT_TRUE(status) << status.error();
  EXPECT_EQ(static_cast<int>(status->lens), 9);
  EXPECT_EQ(to_string(status->state), nullptr);
  EXPECT_FALSE(status->validate());  // but the struct would not be sent as it is
}

TEST(CameraMessages, FixedCommandBytesMustBeTheDocumentedCode) {
  const uint8_t zero[2] = {0x00, 0x00};
  Result<FormatSdRequest> format = decode_payload<FormatSdRequest>(zero, 2);
  ASSERT_FALSE(format);
  EXPECT_EQ(format.error(), "format_sd: byte 1 must be the command code 1, got 0");
  const uint8_t start_not_zero[3] = {0x01, 0x7D, 0x00};
  EXPECT_NE(decode_payload<ZoomRatioRequest>(start_not_zero, 3).error().find("start setting"),
            std::string::npos);
  const uint8_t flag_two[3] = {0x02, 0x00, 0x00};
  EXPECT_NE(decode_payload<OsdWatermarkRequest>(flag_two, 3).error().find("'enabled'"),
            std::string::npos);
}

TEST(CameraMessages, GpsRequestReadsAnyNonZeroLensByteAsEnabled) {
  const uint8_t payload[6] = {0x02, 1, 2, 3, 0xE7, 0x03};
  Result<CameraGpsRequest> request = decode_payload<CameraGpsRequest>(payload, 6);
  ASSERT_TRUE(request);
  EXPECT_TRUE(request->lens_enabled);
  EXPECT_EQ(request->millisecond, 999);
}

TEST(CameraMessages, DataAcksMayCarryTheCodeOnly) {
  const uint8_t refusal[2] = {0x02, 0x04};  // 0x0204 no SD card, big-endian
  Result<GetIpAck> ip = decode_payload<GetIpAck>(refusal, 2);
  ASSERT_TRUE(ip);
  EXPECT_EQ(ip->code, ResponseCode::kNoSdCard);
  EXPECT_EQ(ip->address, "0.0.0.0");
  EXPECT_EQ(decode_payload<CameraVersionAck>(refusal, 2)->code, ResponseCode::kNoSdCard);
  EXPECT_EQ(decode_payload<CameraGpsAck>(refusal, 2)->code, ResponseCode::kNoSdCard);
  EXPECT_EQ(decode_payload<TargetGpsAck>(refusal, 2)->code, ResponseCode::kNoSdCard);
}

// ---- byte order (docs/protocol/decisions.md#a2, section 2.1)
// ---------------------------------------------------------
CodecOptions little_acks() {
  CodecOptions o;
  o.ack_byte_order = ByteOrder::kLittle;
  return o;
}

TEST(CameraMessages, IpAckOctetsAreBytesWhateverTheAckByteOrder) {
  // Section 3.2.4.17: Byte1-2 response code, then each octet a byte of its own, first octet
  // first. ack_byte_order orders the code only: 192.168.144.64 is C0 A8 90 40 either way.
  const GetIpAck ack{ResponseCode::kFailure, "192.168.144.64", "255.255.255.0", "192.168.144.1"};
  Result<Payload> big = encode_payload(ack);
  Result<Payload> little = encode_payload(ack, little_acks());
  ASSERT_TRUE(big && little);
  const std::vector<uint8_t> big_bytes(big->bytes.begin(), big->bytes.begin() + 6);
  const std::vector<uint8_t> little_bytes(little->bytes.begin(), little->bytes.begin() + 6);
  EXPECT_EQ(big_bytes, (std::vector<uint8_t>{0x00, 0x01, 0xC0, 0xA8, 0x90, 0x40}));
  EXPECT_EQ(little_bytes, (std::vector<uint8_t>{0x01, 0x00, 0xC0, 0xA8, 0x90, 0x40}));
  // And read back from a little-endian pod: 00 00 OK, 0A 00 00 07 = 10.0.0.7, not 7.0.0.10.
  const uint8_t wire[14] = {0x00, 0x00, 0x0A, 0x00, 0x00, 0x07, 0xFF,
                            0xFF, 0x00, 0x00, 0x0A, 0x00, 0x00, 0x01};
  Result<GetIpAck> read = decode_payload<GetIpAck>(wire, sizeof(wire), little_acks());
  ASSERT_TRUE(read) << read.error();
  EXPECT_EQ(read->address, "10.0.0.7");
  EXPECT_EQ(read->netmask, "255.255.0.0");
  EXPECT_EQ(read->gateway, "10.0.0.1");
}

TEST(CameraMessages, TargetGpsAckDataIsLowByteFirstWhateverTheAckByteOrder) {
  TargetGpsAck ack = sample<TargetGpsAck>();
  ack.code = ResponseCode::kFailure;
  ack.utc_time_ms = 0x0102030405060708ull;
  Result<Payload> big = encode_payload(ack);
  Result<Payload> little = encode_payload(ack, little_acks());
  ASSERT_TRUE(big && little);
  EXPECT_EQ(big->bytes[0], 0x00);  // the code follows ack_byte_order
  EXPECT_EQ(big->bytes[1], 0x01);
  EXPECT_EQ(little->bytes[0], 0x01);
  EXPECT_EQ(little->bytes[1], 0x00);
  EXPECT_EQ(big->bytes[3], 0x08);  // UTC ms low byte first in both
  EXPECT_EQ(big->bytes[10], 0x01);
  EXPECT_TRUE(
      std::equal(big->bytes.begin() + 2, big->bytes.begin() + 27, little->bytes.begin() + 2));
}

TEST(CameraMessages, StatusFramesAreLowByteFirstWhateverTheAckByteOrder) {
  RecordStatus status;
  status.state = RecordState::kRecording;
  status.recording_time_s = 0x0102;
  for (const CodecOptions& o : {CodecOptions{}, little_acks()}) {
    Result<Payload> p = encode_payload(status, o);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->bytes[2], 0x02);
    EXPECT_EQ(p->bytes[3], 0x01);
  }
}

TEST(CameraMessages, GpsAckIsAnAckInEveryField) {
  CameraGpsAck ack = sample<CameraGpsAck>();
  ack.millisecond = 0x0102;
  Result<Payload> big = encode_payload(ack);
  Result<Payload> little = encode_payload(ack, little_acks());
  ASSERT_TRUE(big && little);
  EXPECT_EQ(big->bytes[5], 0x01);  // millisecond, after code and h/m/s
  EXPECT_EQ(little->bytes[5], 0x02);
}

}  // namespace
}  // namespace k40t::protocol
