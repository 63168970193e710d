// Transparent data from ROS split into commands of at most the DATA limit (transparent_chunks.h):
// 3.2.2 carries 1..128 bytes to the mobile app, 3.6.2 1..255 to the onboard computer.
#include <gtest/gtest.h>

#include "k40t_driver/psdk/commands/app_function.h"
#include "k40t_driver/psdk/commands/osdk_function.h"
#include "k40t_driver/skyport/transparent_chunks.h"

namespace k40t::driver::skyport {
namespace {

using Spans = std::vector<ByteSpan>;

TEST(TransparentChunks, ShortMessageIsOneCommand) {
  EXPECT_EQ(transparent_chunks(1, 128), (Spans{{0, 1}}));
  EXPECT_EQ(transparent_chunks(128, 128), (Spans{{0, 128}}));
}

TEST(TransparentChunks, LongMessageIsFullPiecesThenTheRest) {
  // 300 bytes to the mobile app: 128 + 128 + 44.
  EXPECT_EQ(transparent_chunks(300, psdk::kMaxTransparentToMobile),
            (Spans{{0, 128}, {128, 128}, {256, 44}}));
  // 510 bytes to the onboard computer: exactly two of 255.
  EXPECT_EQ(transparent_chunks(510, psdk::kMaxOsdkTransparent), (Spans{{0, 255}, {255, 255}}));
}

TEST(TransparentChunks, EmptyMessageOrNoRoomSendsNothing) {
  EXPECT_TRUE(transparent_chunks(0, 128).empty());  // the commands carry at least one byte
  EXPECT_TRUE(transparent_chunks(10, 0).empty());
}

}  // namespace
}  // namespace k40t::driver::skyport
