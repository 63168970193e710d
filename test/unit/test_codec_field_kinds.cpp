// The layout field kinds wire::directed (a sign carried as a direction byte, a magnitude scaled by
// a codec option) and wire::ruled (a check that depends on another field), on a small test
// message rather than a pod message, so each rule of the kind is checked by itself.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "message_checks.h"

namespace k40t::protocol {
namespace {

using testing::decode_bytes;
using testing::expect_range_error;

Status check_level(const char* field, bool fine, int level) {
  return fine ? check_range(field, int64_t{level}, 0, 9) : check_range(field, int64_t{level}, 0, 3);
}

// Byte 1 direction (5 = forward, 7 = back, 9 = stay), bytes 2-3 |speed| x angle_command_scale,
// low byte first; byte 4 `fine`; byte 5 a level whose range depends on `fine`.
struct DirectedProbe {
  K40T_POD_REQUEST(0x00FFF0, "directed_probe", "test", 5, 5);
  bool moving = true;
  double speed = 0;
  bool fine = false;
  uint8_t level = 0;

  K40T_LAYOUT(s, v) {
    const auto level_rule = [&s](const char* name, int level) {
      return check_level(name, s.fine, level);
    };
    v("speed_axis", wire::switchable("moving", s.moving, "speed", s.speed),
      wire::directed({5, "forward"}, {7, "back"}, 9, &CodecOptions::angle_command_scale,
                     "angle_command_scale")
          .range(-50, 50, "u"));
    v("fine", s.fine, wire::on_off);
    v("level", s.level, wire::ruled(wire::u8, level_rule));
  }
};

std::vector<uint8_t> encoded(const DirectedProbe& m, const CodecOptions& o = {}) {
  const auto payload = encode_payload(m, o);
  EXPECT_TRUE(payload) << payload.error();
  if (!payload) return {};
  return {payload->data(), payload->data() + payload->size};
}

TEST(CodecFieldKinds, DirectedCarriesTheSignInTheDirectionByte) {
  DirectedProbe m;
  m.speed = 12.34;  // x100 = 1234 = 0x04D2
  EXPECT_EQ(encoded(m), (std::vector<uint8_t>{5, 0xD2, 0x04, 0, 0}));
  m.speed = -0.05;  // 5
  EXPECT_EQ(encoded(m), (std::vector<uint8_t>{7, 0x05, 0x00, 0, 0}));
  m.moving = false;  // "stay": the magnitude is sent as 0 whatever the value
  EXPECT_EQ(encoded(m), (std::vector<uint8_t>{9, 0, 0, 0, 0}));

  const auto back = decode_bytes<DirectedProbe>({7, 0xD2, 0x04, 0, 0});
  ASSERT_TRUE(back) << back.error();
  EXPECT_TRUE(back->moving);
  EXPECT_DOUBLE_EQ(back->speed, -12.34);
  const auto stay = decode_bytes<DirectedProbe>({9, 0xD2, 0x04, 0, 0});
  ASSERT_TRUE(stay) << stay.error();
  EXPECT_FALSE(stay->moving);
  EXPECT_DOUBLE_EQ(stay->speed, 0);
}

TEST(CodecFieldKinds, DirectedTakesItsScaleFromTheCodecOptions) {
  CodecOptions tenths;
  tenths.angle_command_scale = 10;
  DirectedProbe m;
  m.speed = 12.3;  // x10 = 123 = 0x7B
  EXPECT_EQ(encoded(m, tenths), (std::vector<uint8_t>{5, 0x7B, 0x00, 0, 0}));
  const auto back = decode_bytes<DirectedProbe>({5, 0x7B, 0x00, 0, 0}, tenths);
  ASSERT_TRUE(back) << back.error();
  EXPECT_DOUBLE_EQ(back->speed, 12.3);

  CodecOptions zero;
  zero.angle_command_scale = 0;
  const auto refused = decode_bytes<DirectedProbe>({5, 0x7B, 0x00, 0, 0}, zero);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("angle_command_scale must be positive, got 0"), std::string::npos)
      << refused.error();
}

TEST(CodecFieldKinds, DirectedRefusesAnUndefinedDirectionAndChecksItsRange) {
  const auto refused = decode_bytes<DirectedProbe>({6, 0, 0, 0, 0});
  ASSERT_FALSE(refused);
  EXPECT_NE(
      refused.error().find(
          "speed_axis direction byte must be 5 (forward), 7 (back) or 9 (no movement), got 6"),
      std::string::npos)
      << refused.error();

  DirectedProbe m;
  m.speed = -50.5;
  expect_range_error(m, "speed");
  m.moving = false;  // checked whether or not it moves
  expect_range_error(m, "speed");
}

TEST(CodecFieldKinds, RuledChecksWithTheRuleInsteadOfTheTagsRange) {
  DirectedProbe m;
  m.level = 3;
  EXPECT_EQ(encoded(m), (std::vector<uint8_t>{5, 0, 0, 0, 3}));
  m.level = 4;  // coarse: 0..3
  expect_range_error(m, "level");
  m.fine = true;  // fine: 0..9
  EXPECT_EQ(encoded(m), (std::vector<uint8_t>{5, 0, 0, 1, 4}));
  m.level = 10;
  expect_range_error(m, "level");

  const auto back = decode_bytes<DirectedProbe>({5, 0, 0, 1, 10});  // decoding does not check
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->level, 10);
}

TEST(CodecFieldKinds, RuledIsNotAskedOnceAFieldBeforeItFailed) {
  DirectedProbe m;
  m.speed = 99;  // fails first
  m.level = 200;
  const auto refused = encode_payload(m);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("'speed'"), std::string::npos) << refused.error();
}

}  // namespace
}  // namespace k40t::protocol
