// LayoutValidator's range checks test a value itself and call check_range only to write the error
// (codec/layout_validator.h): the bounds stay inclusive, NaN and infinity stay out, the error
// texts stay check_range's, and the first failure in wire order is the one kept.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "k40t_driver/codec/layout.h"

namespace k40t::codec {
namespace {

struct Probe {
  uint8_t level = 5;
  double distance_m = 0;
  double gain = 0;
  float ratio = 0;
  uint8_t mode = 0;

  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("level", s.level, wire::u8.range(1, 10));
    v("distance_m", s.distance_m, wire::scaled<uint16_t>(10).range(0, 6553.5, "m"));
    v("gain", s.gain, wire::scaled<int16_t>(100));  // no range given: what an int16 x0.01 holds
    v("ratio", s.ratio, wire::f32);
    v("config", wire::bit_group(wire::in_bits("mode", s.mode, wire::bits(0, 3))), wire::packed8);
  }
};

Status validate(const Probe& probe) {
  Status result = Status::ok();
  Probe::layout(probe, LayoutValidator(result));
  return result;
}

struct Case {
  const char* what;
  std::function<void(Probe&)> change;
  std::string error;  // empty: valid
};

TEST(LayoutValidator, RangesAreInclusiveAndErrorsAreCheckRangesText) {
  const double nan = std::nan("");
  const std::vector<Case> cases = {
      {"defaults", [](Probe&) {}, ""},
      {"integer at its low bound", [](Probe& p) { p.level = 1; }, ""},
      {"integer at its high bound", [](Probe& p) { p.level = 10; }, ""},
      {"integer below", [](Probe& p) { p.level = 0; }, "field 'level' must be 1..10, got 0"},
      {"integer above", [](Probe& p) { p.level = 11; }, "field 'level' must be 1..10, got 11"},
      {"scaled at its high bound", [](Probe& p) { p.distance_m = 6553.5; }, ""},
      {"scaled below", [](Probe& p) { p.distance_m = -0.1; },
       "field 'distance_m' must be 0..6553.5 m, got -0.1"},
      {"scaled NaN", [nan](Probe& p) { p.distance_m = nan; },
       "field 'distance_m' must be 0..6553.5 m, got nan"},
      {"scaled without a range, at the top of int16", [](Probe& p) { p.gain = 327.67; }, ""},
      {"scaled without a range, past int16", [](Probe& p) { p.gain = 327.68; },
       "field 'gain' must be -327.68..327.67, got 327.68"},
      {"float infinity", [](Probe& p) { p.ratio = std::numeric_limits<float>::infinity(); },
       "field 'ratio' must be -3.40282e+38..3.40282e+38, got inf"},
      {"bit field at its width", [](Probe& p) { p.mode = 7; }, ""},
      {"bit field past its width", [](Probe& p) { p.mode = 8; },
       "field 'mode' must be 0..7, got 8"},
      {"two failures: the first in wire order is kept",
       [](Probe& p) {
         p.level = 0;
         p.distance_m = -1;
       },
       "field 'level' must be 1..10, got 0"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    Probe probe;
    c.change(probe);
    const Status status = validate(probe);
    EXPECT_EQ(status.is_ok(), c.error.empty());
    EXPECT_EQ(status.message(), c.error);
  }
}

}  // namespace
}  // namespace k40t::codec
