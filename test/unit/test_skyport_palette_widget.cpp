// The DJI Pilot palette widget names its items after the pod's palettes (the protocol's names,
// those of cfg/setting_enums.txt), each within the 15 bytes of an item (PSDK 3.2.5), and an item
// sets the palette it names.

#include "k40t_driver/protocol/messages/thermal.h"
#include "skyport_bridge_rig.h"

namespace k40t::driver::skyport {
namespace {

using namespace psdk;
using namespace bridge_testing;

TEST(SkyportPaletteWidget, ItemsAreThePodsPaletteNamesAndSetTheirPalette) {
  Rig rig;
  GetWidgetListData which;
  which.index = 0;
  const Result<WidgetListDataAck> palette = rig.ask(which);
  ASSERT_TRUE(palette);
  ASSERT_EQ(palette->choose_item_count, 10);
  // Names written out from the protocol's (section 3.2.2.3): "white_hot" -> "White hot"; the one
  // longer than 15 bytes, "high_contrast_rainbow", keeps its last word.
  const std::vector<std::pair<std::string, int>> expected{
      {"White hot", 1},    {"Black hot", 2}, {"Rainbow", 3}, {"HC rainbow", 4},
      {"Iron red", 5},     {"Magma", 6},     {"Sky", 7},     {"Medium grey", 8},
      {"Warning red", 12}, {"Ice fire", 13}};
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(palette->choose_items[i], expected[i].first) << i;
    EXPECT_LT(palette->choose_items[i].size(), kChooseItemNameSize);
    SetWidgetValue set;
    set.widget = {WidgetType::kChooseList, 0, static_cast<int32_t>(i)};
    AckResult raw;
    ASSERT_TRUE(rig.ask(set, &raw));
    EXPECT_EQ(raw.code(), 0x00);
    EXPECT_TRUE(has_call(rig.pod, "palette " + std::to_string(expected[i].second))) << i;
  }
}

}  // namespace
}  // namespace k40t::driver::skyport
