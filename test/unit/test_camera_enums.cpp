// The code tables of the common camera family (sections 3.2.1.1, 3.2.1.4, 3.2.4): each enum has
// exactly the document's codes, and the helpers that read them.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "k40t_driver/protocol/messages/camera.h"
#include "message_checks.h"

namespace k40t::protocol {
namespace {

// ---- code tables -------------------------------------------------------------------------------
template <class E>
int defined_codes() {
  return static_cast<int>(testing::defined_codes<E>().size());
}

TEST(CameraEnums, EachTableHasExactlyTheDocumentsCodes) {
  EXPECT_EQ(defined_codes<CaptureMode>(), 2);
  EXPECT_EQ(defined_codes<ReportedStreamResolution>(), 2);
  EXPECT_EQ(defined_codes<StreamResolution>(), 2);
  EXPECT_EQ(defined_codes<VideoEncoding>(), 2);
  EXPECT_EQ(defined_codes<ImageMode>(), 4);
  EXPECT_EQ(defined_codes<StreamBitrate>(), 6);
  EXPECT_EQ(defined_codes<PhotoMode>(), 3);
  EXPECT_EQ(defined_codes<SdCardState>(), 6);
  EXPECT_EQ(defined_codes<CameraUpgradeState>(), 4);
  EXPECT_EQ(defined_codes<PhotoLensMode>(), 4);
  EXPECT_EQ(defined_codes<RecordLensMode>(), 5);
  EXPECT_EQ(defined_codes<PhotoAction>(), 2);
  EXPECT_EQ(defined_codes<RecordAction>(), 2);
  EXPECT_EQ(defined_codes<ZoomCommand>(), 5);
  EXPECT_EQ(defined_codes<ReshootResolution>(), 4);
  EXPECT_EQ(defined_codes<IpMode>(), 2);
  EXPECT_EQ(defined_codes<FocusCommand>(), 8);
  EXPECT_EQ(defined_codes<FeatureSwitch>(), 2);
  EXPECT_EQ(defined_codes<PhotoState>(), 12);
  EXPECT_EQ(defined_codes<ReshootState>(), 13);
  EXPECT_EQ(defined_codes<RecordState>(), 9);
  EXPECT_EQ(defined_codes<ZoomProgress>(), 2);
  EXPECT_EQ(defined_codes<TfUpgradeState>(), 3);
  EXPECT_EQ(defined_codes<SdFormatState>(), 4);
  EXPECT_EQ(defined_codes<GpsFixStatus>(), 9);
}

TEST(CameraEnums, CodesWhereTheDocumentLeavesGaps) {
  EXPECT_EQ(to_string(ImageMode{4}), nullptr);
  EXPECT_STREQ(to_string(ImageMode{5}), "visible");
  EXPECT_EQ(to_string(StreamResolution{0}), nullptr);               // the request counts from 1 ...
  EXPECT_STREQ(to_string(ReportedStreamResolution{0}), "1080P30");  // ... the report from 0
  EXPECT_EQ(to_string(RecordAction{0}), nullptr);
  EXPECT_EQ(to_string(FeatureSwitch{0}), nullptr);
  EXPECT_EQ(to_string(ReshootResolution{0x13}), nullptr);
  EXPECT_STREQ(to_string(ReshootResolution{0x14}), "8000x6000");
  EXPECT_EQ(to_string(StreamBitrate{0}), nullptr);
}

TEST(CameraEnums, BitrateCodesInMegabitsPerSecond) {
  EXPECT_DOUBLE_EQ(bitrate_mbps(StreamBitrate::k1Mbps), 1.0);
  EXPECT_DOUBLE_EQ(bitrate_mbps(StreamBitrate::k1_5Mbps), 1.5);
  EXPECT_DOUBLE_EQ(bitrate_mbps(StreamBitrate::k12Mbps), 12.0);
  EXPECT_DOUBLE_EQ(bitrate_mbps(StreamBitrate{7}), 0.0);
}

TEST(CameraMessages, VersionText) {
  EXPECT_EQ((CameraVersionAck{ResponseCode::kOk, 2, 10, 7}).version_text(), "2.10.7");
}

}  // namespace
}  // namespace k40t::protocol
