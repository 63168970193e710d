// encode_args: message fields from `name=value` text, for every field kind FieldSink knows.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/field_assign.h"
#include "k40t_driver/protocol/messages/laser.h"

namespace k40t::protocol {
namespace {

enum class TestPalette : uint8_t { kWhiteHot = 1, kBlackHot = 2, kHighContrastRainbow = 4 };
const char* to_string(TestPalette p) {
  switch (p) {
    case TestPalette::kWhiteHot: return "white hot";
    case TestPalette::kBlackHot: return "black hot";
    case TestPalette::kHighContrastRainbow: return "high-contrast rainbow";
  }
  return nullptr;
}

// Every field kind, with a made-up layout: the test is about text -> fields -> bytes.
struct AllKinds {
  static constexpr MessageId kId = 0x0000F0;
  static constexpr const char* kName = "all_kinds";
  static constexpr const char* kSection = "test";
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 20;
  static constexpr size_t kMinSize = 20;

  int8_t small = 0;
  uint16_t count = 0;
  double angle_deg = 0;
  bool on = false;
  TestPalette palette = TestPalette::kWhiteHot;
  std::string folder;
  std::array<uint8_t, 4> ip{};

  Status validate() const {
    return first_failure(check_range("angle_deg", angle_deg, -90.0, 90.0, "deg"),
                         check_enum("palette", palette), check_text("folder", folder, 8));
  }
  void encode(ByteWriter& w, const CodecOptions&) const {
    w.i8(small);
    w.u16(count);
    w.i16(to_wire<int16_t>(angle_deg, 100));
    w.u8(on ? 1 : 0);
    w.u8(static_cast<uint8_t>(palette));
    w.text(folder, 8);
    for (uint8_t b : ip) w.u8(b);
    w.zeros(1);
  }
  Status decode(ByteReader&, const CodecOptions&) { return Status::ok(); }
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("small", self.small);
    v("count", self.count);
    v("angle_deg", self.angle_deg);
    v("on", self.on);
    v("palette", self.palette);
    v("folder", self.folder);
    v("ip", self.ip);
  }
};

std::vector<uint8_t> bytes(const Payload& p) { return std::vector<uint8_t>(p.data(), p.data() + p.size); }

TEST(EncodeArgs, EveryKindFromText) {
  const Result<Payload> p = encode_args<AllKinds>({{"small", "-5"},
                                                   {"count", "0x1234"},
                                                   {"angle_deg", "-12.5"},
                                                   {"on", "true"},
                                                   {"palette", "High Contrast_Rainbow"},
                                                   {"folder", "DCIM"},
                                                   {"ip", "192.168.144.64"}},
                                                  CodecOptions{});
  ASSERT_TRUE(p) << p.error();
  EXPECT_EQ(bytes(*p), (std::vector<uint8_t>{0xFB, 0x34, 0x12, 0x1E, 0xFB, 0x01, 0x04, 'D', 'C', 'I',
                                             'M', 0, 0, 0, 0, 192, 168, 144, 64, 0x00}));
}

TEST(EncodeArgs, MissingFieldsKeepTheirDefaults) {
  const Result<AllKinds> m = message_from_args<AllKinds>({{"count", "08"}});  // decimal, not octal
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->count, 8);
  EXPECT_EQ(m->palette, TestPalette::kWhiteHot);
  EXPECT_EQ(m->ip, (std::array<uint8_t, 4>{0, 0, 0, 0}));
}

TEST(EncodeArgs, EnumByCodeOrName) {
  EXPECT_EQ(message_from_args<AllKinds>({{"palette", "2"}})->palette, TestPalette::kBlackHot);
  EXPECT_EQ(message_from_args<AllKinds>({{"palette", "black_hot"}})->palette, TestPalette::kBlackHot);
  const Result<AllKinds> bad = message_from_args<AllKinds>({{"palette", "sepia"}});
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("'palette'"), std::string::npos) << bad.error();
  EXPECT_NE(bad.error().find("1 white_hot, 2 black_hot, 4 high_contrast_rainbow"), std::string::npos)
      << bad.error();
  // An undefined numeric code parses; validation (check_enum) then rejects it with the list.
  const Result<Payload> undefined = encode_args<AllKinds>({{"palette", "3"}}, CodecOptions{});
  ASSERT_FALSE(undefined);
  EXPECT_NE(undefined.error().find("no code 3"), std::string::npos) << undefined.error();
}

struct BadArg {
  std::string name;
  std::string value;
  std::string expected;  // a piece of the error message
};

TEST(EncodeArgs, BadValuesNameTheFieldAndTheRule) {
  const std::vector<BadArg> cases = {
      {"small", "-129", "must be -128..127"},
      {"small", "12abc", "expected an integer"},
      {"count", "-1", "must be 0..65535"},
      {"count", "65536", "must be 0..65535"},
      {"count", " 5", "expected an integer"},
      {"angle_deg", "north", "expected a finite number"},
      {"angle_deg", "nan", "expected a finite number"},
      {"angle_deg", "", "expected a finite number"},
      {"angle_deg", "95", "must be -90..90 deg"},  // from validate()
      {"on", "yes", "expected 0, 1, true or false"},
      {"folder", "a_very_long_folder", "at most 8 bytes"},
      {"ip", "1,2,3", "expected 4 numbers"},
      {"ip", "1,2,3,4,5", "expected 4 numbers"},
      {"ip", "1,2,3,256", "expected 4 numbers"},
      {"ip", "1,,3,4", "expected 4 numbers"},
  };
  for (const BadArg& c : cases) {
    const Result<Payload> p = encode_args<AllKinds>({{c.name, c.value}}, CodecOptions{});
    ASSERT_FALSE(p) << c.name << "=" << c.value;
    EXPECT_NE(p.error().find(c.expected), std::string::npos) << c.name << "=" << c.value << ": " << p.error();
    EXPECT_NE(p.error().find(c.name), std::string::npos) << p.error();
  }
}

TEST(EncodeArgs, UnknownNamesListTheFields) {
  const Result<Payload> p = encode_args<AllKinds>({{"colour", "1"}, {"count", "1"}, {"zz", "2"}}, CodecOptions{});
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error(),
            "all_kinds has no fields 'colour', 'zz'; its fields: small, count, angle_deg, on, palette, "
            "folder, ip");
}

TEST(EncodeArgs, ThroughTheCatalogue) {
  const MessageInfo* info = find_message("laser_range");
  ASSERT_NE(info, nullptr);
  ASSERT_NE(info->encode_args, nullptr);
  // Section 3.2.5.1: byte 1 enable (1 single ranging), byte 2 reserved.
  const Result<Payload> on = info->encode_args({{"enable", "1"}}, CodecOptions{});
  ASSERT_TRUE(on) << on.error();
  EXPECT_EQ(bytes(*on), (std::vector<uint8_t>{0x01, 0x00}));
  const Result<Payload> off = info->encode_args({{"enable", "false"}}, CodecOptions{});
  ASSERT_TRUE(off);
  EXPECT_EQ(bytes(*off), (std::vector<uint8_t>{0x00, 0x00}));
  const Result<Payload> bad = info->encode_args({{"distance", "3"}}, CodecOptions{});
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error(), "laser_range has no field 'distance'; its fields: enable");
}

TEST(EncodeArgs, NormalizeLabel) {
  EXPECT_EQ(normalize_label("OK, success"), "ok_success");
  EXPECT_EQ(normalize_label("  white  hot "), "white_hot");
  EXPECT_EQ(normalize_label("1080P30"), "1080p30");
}

}  // namespace
}  // namespace k40t::protocol
