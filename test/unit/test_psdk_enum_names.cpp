// The PSDK enums' names come from tables (codec/enum_names.h): each code the document defines has
// its name, and a code next to the listed ones (below the first, past the last, in a gap) has
// none, which is what check_enum() reports as out of range.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "k40t_driver/psdk/commands/all.h"

namespace k40t::psdk {
namespace {

struct NameCase {
  const char* name;  // what to_string() gives, nullptr for a code without a name
  const char* actual;
};

template <class E>
NameCase name_of(uint8_t code, const char* name) {
  return {name, to_string(static_cast<E>(code))};
}

// EXPECT_STREQ takes two null pointers as equal, and a null pointer and a name as different.
void expect_names(std::initializer_list<NameCase> cases) {
  for (const NameCase& c : cases) EXPECT_STREQ(c.actual, c.name);
}

TEST(PsdkEnumNames, EachCodeHasItsNameAndTheCodesBesideHaveNone) {
  expect_names({
      // Codes without gaps, from their first code.
      name_of<CommandSet>(0x00, nullptr),
      name_of<CommandSet>(0x01, "payload_state"),
      name_of<CommandSet>(0x07, "positioning"),
      name_of<CommandSet>(0x08, nullptr),
      name_of<AckCode>(0x02, "unsupported"),
      name_of<AckCode>(0x03, nullptr),
      name_of<ZoomSpeed>(71, nullptr),
      name_of<ZoomSpeed>(72, "slowest"),
      name_of<ZoomSpeed>(75, "normal"),
      name_of<ZoomSpeed>(78, "fastest"),
      name_of<ZoomSpeed>(79, nullptr),
      name_of<DroneType>(0, "unknown"),
      name_of<DroneType>(8, "M210 RTK V2"),
      name_of<DroneType>(9, nullptr),
      name_of<WidgetType>(0, nullptr),
      name_of<WidgetType>(1, "button"),
      name_of<WidgetType>(5, "integer_input_box"),
      name_of<GimbalMode>(1, "fpv"),
      name_of<GimbalStateMode>(1, "following"),
      // Codes with gaps, paired with their names.
      name_of<ShootPhotoType>(1, "single"),
      name_of<ShootPhotoType>(2, nullptr),
      name_of<ShootPhotoType>(4, "burst"),
      name_of<ShootPhotoType>(6, "interval"),
      name_of<PositionSolution>(0, "not_available"),
      name_of<PositionSolution>(16, "single_point"),
      name_of<PositionSolution>(17, nullptr),
      name_of<PositionSolution>(50, "fixed"),
  });
}

TEST(PsdkEnumNames, AckCodeText) {
  EXPECT_EQ(ack_code_text(0x00), "executed successfully");
  EXPECT_EQ(ack_code_text(0x01), "executed unsuccessfully");
  EXPECT_EQ(ack_code_text(0x02), "command not supported");
  EXPECT_EQ(ack_code_text(0x03), "unknown return code 0x03");
}

}  // namespace
}  // namespace k40t::psdk
