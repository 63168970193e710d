// name_in() (codec/enum_names.h): each value's own text, and the fallback for a value the table
// lacks (a byte off the wire cast to the enum).
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

}  // namespace
}  // namespace k40t
