// parse_version() (skyport/version_text.h): the firmware_version and skyport_version parameters,
// "A.B.C.D" with each part 0..255 (3.1.2: 0xAABBCCDD is version AA.BB.CC.DD).
#include <gtest/gtest.h>

#include "k40t_driver/skyport/version_text.h"

namespace k40t::driver::skyport {
namespace {

TEST(SkyportVersionText, ReadsEachPartInOrder) {
  struct Case {
    const char* text;
    uint8_t major, minor, modify, debug;
  };
  for (const Case& c : {Case{"1.2.3.4", 1, 2, 3, 4}, Case{"255.0.0.255", 255, 0, 0, 255},
                        Case{"0.0.0.0", 0, 0, 0, 0}, Case{"03.10.0.7", 3, 10, 0, 7}}) {
    psdk::Version v;
    ASSERT_TRUE(parse_version(c.text, v)) << c.text;
    EXPECT_EQ(v.major, c.major) << c.text;
    EXPECT_EQ(v.minor, c.minor) << c.text;
    EXPECT_EQ(v.modify, c.modify) << c.text;
    EXPECT_EQ(v.debug, c.debug) << c.text;
  }
}

TEST(SkyportVersionText, RefusesAnythingElseAndKeepsTheValue) {
  for (const char* text : {"", "1.2.3", "1.2.3.4.5", "1.2.3.4x", "1.2.3.256", "256.0.0.0",
                           "-1.0.0.0", "a.b.c.d", "1,2,3,4"}) {
    psdk::Version v{9, 8, 7, 6};
    EXPECT_FALSE(parse_version(text, v)) << text;
    EXPECT_EQ(v.major, 9) << text;
    EXPECT_EQ(v.minor, 8) << text;
    EXPECT_EQ(v.modify, 7) << text;
    EXPECT_EQ(v.debug, 6) << text;
  }
}

}  // namespace
}  // namespace k40t::driver::skyport
