// The 20 thermal palettes (sim/video/palette.h).
#include <gtest/gtest.h>

#include <set>

#include "k40t_driver/sim/video/palette.h"

namespace k40t::sim::video {
namespace {

cv::Vec3b entry(const cv::Mat& table, int i) {
  return table.at<cv::Vec3b>(0, i);
}

TEST(Palette, EveryCodeHasATableOfItsOwn) {
  std::set<std::vector<uint8_t>> tables;
  std::set<std::string> names;
  for (int p = kFirstPalette; p <= kLastPalette; ++p) {
    Result<cv::Mat> table = palette_table(p);
    ASSERT_TRUE(table) << table.error();
    ASSERT_EQ(table->size(), cv::Size(256, 1));
    ASSERT_EQ(table->type(), CV_8UC3);
    tables.insert(std::vector<uint8_t>(table->datastart, table->dataend));
    names.insert(palette_name(p).value());
  }
  EXPECT_EQ(tables.size(), 20u);
  EXPECT_EQ(names.size(), 20u);
}

TEST(Palette, WhiteHotAndBlackHotAreGreyRampsInOppositeDirections) {
  const cv::Mat white = palette_table(1).value();
  const cv::Mat black = palette_table(2).value();
  EXPECT_EQ(palette_name(1).value(), "white_hot");
  EXPECT_EQ(palette_name(2).value(), "black_hot");
  for (int i = 0; i < 256; ++i) {
    const cv::Vec3b w = entry(white, i);
    EXPECT_EQ(w[0], w[1]);
    EXPECT_EQ(w[1], w[2]);
    EXPECT_NEAR(w[0], i, 1);
    EXPECT_NEAR(entry(black, i)[0], 255 - i, 1);
  }
}

TEST(Palette, IronRedRunsFromDarkToBrightThroughRed) {
  const cv::Mat iron = palette_table(5).value();
  EXPECT_EQ(palette_name(5).value(), "iron_red");
  const cv::Vec3b cold = entry(iron, 0);
  const cv::Vec3b warm = entry(iron, 141);  // 0.55: the red stop
  const cv::Vec3b hot = entry(iron, 255);
  EXPECT_LT(cold[0] + cold[1] + cold[2], 30);
  EXPECT_GT(warm[2], 200);  // red dominates (BGR)
  EXPECT_LT(warm[1], 80);
  EXPECT_GT(hot[0] + hot[1] + hot[2], 700);
}

TEST(Palette, CodesOutsideOneToTwentyAreNamedInTheError) {
  for (int bad : {0, 21, -3}) {
    Result<cv::Mat> table = palette_table(bad);
    ASSERT_FALSE(table);
    EXPECT_NE(table.error().find(std::to_string(bad)), std::string::npos) << table.error();
    EXPECT_NE(table.error().find("1..20"), std::string::npos);
    EXPECT_FALSE(palette_name(bad));
  }
}

}  // namespace
}  // namespace k40t::sim::video
