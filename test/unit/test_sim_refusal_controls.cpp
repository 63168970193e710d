// The simulator's control commands added for issue 10: `refuse ID [CODE]` (a request refused with
// a code and not carried out, for partial failures such as sbus/set's) and `photo-resolution`
// (a value 0x010200 reports that no setting request can make, 3.2.3.1 byte 3).
#include <gtest/gtest.h>

#include "k40t_driver/sim/control_commands.h"
#include "k40t_driver/sim/fault_injector.h"
#include "sim_control_target.h"

namespace k40t::sim {
namespace {

using testing::FakeTarget;

TEST(SimRefuse, NamesOneRequestIdWithItsCode) {
  FakeTarget target;
  EXPECT_EQ(execute_control_command("refuse 0x000501", target).rfind("ok", 0), 0u);
  ASSERT_TRUE(target.faults_.refusal(0x000501).has_value());
  EXPECT_EQ(*target.faults_.refusal(0x000501), 0x0001);  // failure (section 3.3) by default
  EXPECT_FALSE(target.faults_.refusal(0x000500).has_value());
  EXPECT_EQ(execute_control_command("refuse 0x000500 0x0204", target).rfind("ok", 0), 0u);
  EXPECT_EQ(*target.faults_.refusal(0x000500), 0x0204);
  EXPECT_FALSE(target.faults_.refusal(0x000501).has_value());
}

TEST(SimRefuse, ZeroAndClearTurnItOff) {
  FakeTarget target;
  ASSERT_EQ(execute_control_command("refuse 0x000501", target).rfind("ok", 0), 0u);
  EXPECT_EQ(execute_control_command("refuse 0", target).rfind("ok", 0), 0u);
  EXPECT_FALSE(target.faults_.refusal(0x000501).has_value());
  ASSERT_EQ(execute_control_command("refuse 0x000501", target).rfind("ok", 0), 0u);
  EXPECT_EQ(execute_control_command("clear", target).rfind("ok", 0), 0u);
  EXPECT_FALSE(target.faults_.refusal(0x000501).has_value());
}

TEST(SimRefuse, BadArgumentsAreErrors) {
  FakeTarget target;
  EXPECT_EQ(execute_control_command("refuse 0x1000000", target).rfind("error: ID must be", 0), 0u);
  EXPECT_EQ(execute_control_command("refuse 0x000501 0", target).rfind("error: CODE must be", 0),
            0u);
}

TEST(SimPhotoResolution, SetsWhatTheCameraReports) {
  FakeTarget target;
  EXPECT_EQ(execute_control_command("photo-resolution 0x16", target).rfind("ok", 0), 0u);
  EXPECT_EQ(target.pod.camera().visible().photo_resolution, protocol::PhotoResolution::k5160x3870);
  EXPECT_EQ(execute_control_command("photo-resolution 0x17", target).rfind("error", 0), 0u);
  EXPECT_EQ(target.pod.camera().visible().photo_resolution, protocol::PhotoResolution::k5160x3870);
}

}  // namespace
}  // namespace k40t::sim
