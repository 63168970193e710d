// name_in() and lookup() (codec/enum_names.h): each value's own text or value, and the fallback
// for a value the table lacks (a byte off the wire cast to the enum, or a mapping's default).
#include <gtest/gtest.h>

#include <cstring>

#include "k40t_driver/codec/enum_names.h"

namespace k40t {
namespace {

enum class Colour { kRed = 1, kGreen = 2, kBlue = 7 };

constexpr EnumName<Colour> kColours[] = {
    {Colour::kRed, "red"}, {Colour::kGreen, "green"}, {Colour::kBlue, "blue"}};

TEST(EnumNames, NamesEachValue) {
  EXPECT_STREQ(name_in(kColours, Colour::kRed), "red");
  EXPECT_STREQ(name_in(kColours, Colour::kGreen), "green");
  EXPECT_STREQ(name_in(kColours, Colour::kBlue), "blue");
  static_assert(std::strlen(name_in(kColours, Colour::kBlue)) == 4, "usable at compile time");
}

TEST(EnumNames, FallsBackForAValueNotInTheTable) {
  EXPECT_STREQ(name_in(kColours, static_cast<Colour>(3)), "?");
  EXPECT_STREQ(name_in(kColours, static_cast<Colour>(0), "no colour"), "no colour");
}

TEST(EnumNames, MapsToOtherValuesWithADefault) {
  static constexpr EnumTo<Colour, int> kWavelengths[] = {{Colour::kRed, 700}, {Colour::kBlue, 450}};
  EXPECT_EQ(lookup(kWavelengths, Colour::kRed, 0), 700);
  EXPECT_EQ(lookup(kWavelengths, Colour::kBlue, 0), 450);
  EXPECT_EQ(lookup(kWavelengths, Colour::kGreen, -1), -1);
}

}  // namespace
}  // namespace k40t
