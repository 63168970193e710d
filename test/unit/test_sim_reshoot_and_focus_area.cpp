// The simulator honours what 0x000307 and 0x000313 carry beyond their mode byte: the precise
// re-shoot's resolution byte (section 3.2.4.7) and the focus area's corners (section 3.2.4.18).
// Requests are written byte by byte from the document, so a driver that put a field in the
// wrong place would be caught by what the simulator does.
#include <gtest/gtest.h>

#include <vector>

#include "k40t_driver/protocol/messages/camera.h"
#include "sim_pod_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;
using p::ResponseCode;
using testing::PodHarness;
using testing::SimPodTest;
using SimFocus = SimPodTest;

// 0x000307: byte 1 lens, byte 2 resolution, bytes 3-4 zoom x10 and 5-6 focal (low byte first),
// bytes 7-26 folder, 27-58 name.
std::vector<uint8_t> reshoot_bytes(uint8_t lens, uint8_t resolution) {
  std::vector<uint8_t> bytes(58, 0x00);
  bytes[0] = lens;
  bytes[1] = resolution;
  bytes[2] = 0x50;  // 80 = 8.0x
  bytes[3] = 0x00;
  bytes[4] = 0xB0;  // 0x0EB0 = 3760
  bytes[5] = 0x0E;
  return bytes;
}

ResponseCode code_of(PodHarness& h, const std::optional<p::Payload>& ack) {
  if (!ack) return ResponseCode::kTimeout;
  return p::ack_response_code(ack->data(), ack->size, h.codec);
}

TEST(SimReshoot, ThePhotoHasTheResolutionOfByte2NotThePhotoSetting) {
  const struct {
    uint8_t code;
    uint16_t width;
    uint16_t height;
  } cases[] = {{0x14, 8000, 6000}, {0x15, 4000, 3000}, {0x16, 5160, 3890}, {0x17, 5664, 4248}};
  for (const auto& c : cases) {
    PodHarness h;  // photo setting 0x15 (4000x3000)
    EXPECT_EQ(code_of(h, h.raw(0x000307, reshoot_bytes(0x02, c.code))), ResponseCode::kOk);
    h.run(3.0);
    ASSERT_EQ(h.pod.camera().photos().size(), 1u) << int{c.code};
    EXPECT_EQ(h.pod.camera().photos()[0].width_px, c.width) << int{c.code};
    EXPECT_EQ(h.pod.camera().photos()[0].height_px, c.height) << int{c.code};
  }
}

TEST(SimReshoot, BiggerResolutionsFillMoreOfTheCard) {
  PodHarness small;
  PodHarness large;
  ASSERT_EQ(code_of(small, small.raw(0x000307, reshoot_bytes(0x02, 0x15))), ResponseCode::kOk);
  ASSERT_EQ(code_of(large, large.raw(0x000307, reshoot_bytes(0x02, 0x17))), ResponseCode::kOk);
  small.run(3.0);
  large.run(3.0);
  ASSERT_EQ(small.pod.camera().photos().size(), 1u);
  ASSERT_EQ(large.pod.camera().photos().size(), 1u);
  EXPECT_GT(large.pod.camera().photos()[0].size_mb, small.pod.camera().photos()[0].size_mb);
}

TEST(SimReshoot, AnUnlistedResolutionIsRefusedAndNothingIsShot) {
  PodHarness h;
  EXPECT_NE(code_of(h, h.raw(0x000307, reshoot_bytes(0x02, 0x18))), ResponseCode::kOk);
  h.run(3.0);
  EXPECT_TRUE(h.pod.camera().photos().empty());
}

// 0x000313: byte 1 mode, bytes 2-9 left, top, right, bottom (uint16 low byte first), byte 10.
std::vector<uint8_t> focus_bytes(uint8_t mode, uint16_t left, uint16_t top, uint16_t right,
                                 uint16_t bottom) {
  std::vector<uint8_t> bytes{mode};
  for (uint16_t v : {left, top, right, bottom}) {
    bytes.push_back(static_cast<uint8_t>(v & 0xFF));
    bytes.push_back(static_cast<uint8_t>(v >> 8));
  }
  bytes.push_back(0x00);
  return bytes;
}

TEST_F(SimFocus, AreaAutoFocusUsesTheCorners) {
  ASSERT_EQ(code_of(h, h.raw(0x000313, focus_bytes(0x04, 800, 400, 1120, 680))), ResponseCode::kOk);
  ASSERT_TRUE(h.pod.zoom().focus_area().has_value());
  EXPECT_EQ(h.pod.zoom().focus_area()->left, 800);
  EXPECT_EQ(h.pod.zoom().focus_area()->top, 400);
  EXPECT_EQ(h.pod.zoom().focus_area()->right, 1120);
  EXPECT_EQ(h.pod.zoom().focus_area()->bottom, 680);
  EXPECT_TRUE(h.pod.zoom().focusing());
}

TEST_F(SimFocus, AnEmptyOrOutsideAreaIsRefused) {
  EXPECT_NE(code_of(h, h.raw(0x000313, focus_bytes(0x04, 800, 400, 800, 680))), ResponseCode::kOk);
  EXPECT_NE(code_of(h, h.raw(0x000313, focus_bytes(0x04, 800, 400, 1921, 680))), ResponseCode::kOk);
  EXPECT_FALSE(h.pod.zoom().focus_area().has_value());
}

TEST_F(SimFocus, OneTouchAndZoomGoBackToCentreFocus) {
  ASSERT_EQ(code_of(h, h.raw(0x000313, focus_bytes(0x04, 10, 10, 200, 200))), ResponseCode::kOk);
  ASSERT_EQ(code_of(h, h.raw(0x000313, focus_bytes(0x05, 0, 0, 0, 0))), ResponseCode::kOk);
  EXPECT_FALSE(h.pod.zoom().focus_area().has_value());
  ASSERT_EQ(code_of(h, h.raw(0x000313, focus_bytes(0x04, 10, 10, 200, 200))), ResponseCode::kOk);
  p::ZoomRatioRequest zoom;
  zoom.zoom_x = 4.0;
  ASSERT_EQ(h.send(zoom), ResponseCode::kOk);
  EXPECT_FALSE(h.pod.zoom().focus_area().has_value());
}

}  // namespace
}  // namespace k40t::sim
