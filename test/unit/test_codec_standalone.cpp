// codec/ stands below both protocols: this file includes codec/ headers only (no protocol/, no
// psdk/), and a message family of its own, with its own options type, describes a message with the
// declarative layouts, as the pod protocol does with its CodecOptions and the PSDK with none.
// scripts/check_layers.py checks the includes of codec/ itself; this checks what it can do alone.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "k40t_driver/codec/byte_io.h"
#include "k40t_driver/codec/field_visit.h"
#include "k40t_driver/codec/layout.h"
#include "k40t_driver/codec/result.h"
#include "k40t_driver/codec/value_checks.h"

namespace k40t::codec {
namespace {

// A family's own options: the scale its directed field takes.
struct WinchOptions {
  int rope_scale = 100;
};

// Byte 1 direction (1 = out, 2 = in, 0 = hold), bytes 2-3 |length_m| x rope_scale, low byte
// first; byte 4 a speed 1..5.
struct WinchRequest {
  bool moving = true;
  double length_m = 0;
  uint8_t speed = 1;

  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("rope", wire::switchable("moving", s.moving, "length_m", s.length_m),
      wire::directed({1, "out"}, {2, "in"}, 0, &WinchOptions::rope_scale, "rope_scale")
          .range(-20, 20, "m"));
    v("speed", s.speed, wire::u8.range(1, 5));
  }
};

std::vector<uint8_t> encode(const WinchRequest& m, const WinchOptions* options) {
  std::array<uint8_t, 8> buffer{};
  ByteWriter w(buffer.data(), buffer.size());
  WinchRequest::layout(m,
                       BasicLayoutWriter<ByteOrder::kLittle, ByteWriter, WinchOptions>(w, options));
  EXPECT_TRUE(w.ok());
  return {buffer.data(), buffer.data() + w.size()};
}

Status decode(const std::vector<uint8_t>& bytes, const WinchOptions* options, WinchRequest& m) {
  ByteReader r(bytes.data(), bytes.size());
  Status failure = Status::ok();
  WinchRequest::layout(m, BasicLayoutReader<ByteOrder::kLittle, ByteReader, WinchOptions>(
                              r, bytes.size(), &failure, options));
  return failure;
}

TEST(CodecStandalone, ADirectedFieldTakesItsScaleFromTheFamilysOwnOptions) {
  WinchRequest m;
  m.length_m = -2.5;  // in, 2.5 x 100 = 250 = 0x00FA
  m.speed = 3;
  EXPECT_EQ(encode(m, nullptr), (std::vector<uint8_t>{2, 0xFA, 0x00, 3}));  // defaults: 100
  WinchOptions tenths;
  tenths.rope_scale = 10;  // 2.5 x 10 = 25 = 0x19
  EXPECT_EQ(encode(m, &tenths), (std::vector<uint8_t>{2, 0x19, 0x00, 3}));

  WinchRequest back;
  ASSERT_TRUE(decode({1, 0x19, 0x00, 5}, &tenths, back));
  EXPECT_TRUE(back.moving);
  EXPECT_DOUBLE_EQ(back.length_m, 2.5);
  EXPECT_EQ(back.speed, 5);
}

TEST(CodecStandalone, TheFamilysOptionAndDirectionCodesNameThemselvesInErrors) {
  WinchOptions zero;
  zero.rope_scale = 0;
  WinchRequest m;
  const Status no_scale = decode({1, 0x19, 0x00, 5}, &zero, m);
  EXPECT_EQ(no_scale.message(), "rope_scale must be positive, got 0");
  const Status bad_direction = decode({3, 0, 0, 1}, nullptr, m);
  EXPECT_EQ(bad_direction.message(),
            "rope direction byte must be 1 (out), 2 (in) or 0 (no movement), got 3");
}

TEST(CodecStandalone, TheValidatorAndTheSizerNeedNoOptions) {
  WinchRequest m;
  m.speed = 6;
  Status result = Status::ok();
  WinchRequest::layout(m, LayoutValidator(result));
  EXPECT_EQ(result.message(), "field 'speed' must be 1..5, got 6");
  m.speed = 5;
  m.length_m = 20.5;
  result = Status::ok();
  WinchRequest::layout(m, LayoutValidator(result));
  EXPECT_EQ(result.message(), "field 'length_m' must be -20..20 m, got 20.5");

  size_t size = 0;
  WinchRequest::layout(m, LayoutSizer(size));
  EXPECT_EQ(size, 4u);
}

// A FieldSink that writes "name=value" lines: the fields reach it through the codec alone.
class TextSink : public FieldSink {
 public:
  std::string lines;
  void integer(const char* name, int64_t v) override { add(name, std::to_string(v)); }
  void unsigned_integer(const char* name, uint64_t v) override { add(name, std::to_string(v)); }
  void real(const char* name, double v) override { add(name, std::to_string(v)); }
  void boolean(const char* name, bool v) override { add(name, v ? "true" : "false"); }
  void text(const char* name, const std::string& v) override { add(name, v); }
  void enumeration(const char* name, int64_t code, const char*) override {
    add(name, std::to_string(code));
  }
  void bytes(const char* name, const uint8_t*, size_t size) override {
    add(name, std::to_string(size) + " bytes");
  }

 private:
  void add(const char* name, const std::string& value) {
    lines += std::string(name) + "=" + value + "\n";
  }
};

TEST(CodecStandalone, FieldsReachAFieldSinkWithoutTheProtocol) {
  WinchRequest m;
  m.length_m = 1.5;
  m.speed = 2;
  TextSink sink;
  WinchRequest::layout(m, LayoutSink(sink));
  EXPECT_EQ(sink.lines, "moving=true\nlength_m=1.500000\nspeed=2\n");
}

}  // namespace
}  // namespace k40t::codec
