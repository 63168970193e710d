// Frame layout (document section 2.1). The golden bytes below were written by hand from the
// document; the checksum bytes were computed with the document's crc_accumulate routine run
// independently of this code base (test/data/README.md explains how).
#include <gtest/gtest.h>

#include <vector>

#include "k40t_driver/protocol/frame.h"

namespace k40t::protocol {
namespace {

// Section 3.2.5.1: single laser ranging, host 0x01/0x01 -> camera 0x04/0x01, SEQ 0,
// MSGID 0x000400 low byte first, payload {0x01 enable single ranging, 0x00 reserved}.
const std::vector<uint8_t> kLaserRequestHeaderExcluded = {0xFD, 0x02, 0x04, 0x01, 0x00, 0x01, 0x01,
                                                          0x00, 0x04, 0x00, 0x01, 0x00, 0xA2, 0x56};
const std::vector<uint8_t> kLaserRequestWholeFrame = {0xFD, 0x02, 0x04, 0x01, 0x00, 0x01, 0x01,
                                                      0x00, 0x04, 0x00, 0x01, 0x00, 0xAF, 0x74};

FrameHeader laser_header() {
  FrameHeader h;
  h.destination = kCameraAddress;
  h.sequence = 0;
  h.source = kHostAddress;
  h.message_id = 0x000400;
  return h;
}

TEST(Frame, EncodesTheDocumentsLayoutHeaderExcluded) {
  const uint8_t payload[] = {0x01, 0x00};
  auto frame = encode_frame(laser_header(), payload, 2, CrcCoverage::kHeaderExcluded);
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(std::vector<uint8_t>(frame->data(), frame->data() + frame->size()), kLaserRequestHeaderExcluded);
}

TEST(Frame, EncodesWholeFrameCoverage) {
  const uint8_t payload[] = {0x01, 0x00};
  auto frame = encode_frame(laser_header(), payload, 2, CrcCoverage::kWholeFrame);
  ASSERT_TRUE(frame);
  EXPECT_EQ(std::vector<uint8_t>(frame->data(), frame->data() + frame->size()), kLaserRequestWholeFrame);
}

TEST(Frame, AutoCoverageSendsHeaderExcluded) {
  const uint8_t payload[] = {0x01, 0x00};
  auto frame = encode_frame(laser_header(), payload, 2, CrcCoverage::kAuto);
  ASSERT_TRUE(frame);
  EXPECT_EQ(std::vector<uint8_t>(frame->data(), frame->data() + frame->size()), kLaserRequestHeaderExcluded);
}

TEST(Frame, RejectsOversizedPayload) {
  std::vector<uint8_t> payload(244, 0);
  auto frame = encode_frame(laser_header(), payload.data(), payload.size(), CrcCoverage::kHeaderExcluded);
  ASSERT_FALSE(frame);
  EXPECT_NE(frame.error().find("243"), std::string::npos) << frame.error();
}

TEST(Frame, AcceptsMaximumPayload) {
  std::vector<uint8_t> payload(243, 0x5A);
  auto frame = encode_frame(laser_header(), payload.data(), payload.size(), CrcCoverage::kHeaderExcluded);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->size(), 255u);
  EXPECT_EQ(frame->data()[1], 243);
}

TEST(Frame, RejectsIdOver24Bits) {
  FrameHeader h = laser_header();
  h.message_id = 0x1000000;
  EXPECT_FALSE(encode_frame(h, nullptr, 0, CrcCoverage::kHeaderExcluded));
}

}  // namespace
}  // namespace k40t::protocol
