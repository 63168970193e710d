// Typed golden tests of the common camera family: every frame of test/data/golden/camera.txt,
// written by hand from the document (sections 3.2.1.1, 3.2.1.4, 3.2.4), is parsed, decoded with
// its struct and compared with the file's expected field values; then the struct is built from
// those values alone, encoded, and must give back the hand-written bytes.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "field_assigner.h"
#include "golden_checks.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/parser.h"
#include "message_text.h"

namespace k40t::protocol {
namespace {

using testing::assign_fields;
using testing::decode_golden;
using testing::expect_encodes_to;
using testing::fields_match;
using testing::GoldenFrame;
using testing::message_from_text;
using testing::record_fields;
using testing::set_fields;

const char kFile[] = "camera.txt";

struct Route {
  Address source;
  Address destination;
};
constexpr Route kToCamera{kHostAddress, kCameraAddress};
constexpr Route kFromCamera{kCameraAddress, kHostAddress};
constexpr Route kFlightControllerToCamera{kFlightControllerAddress, kCameraAddress};
constexpr Route kCameraToFlightController{kCameraAddress, kFlightControllerAddress};

template <class T>
void check_golden(const GoldenFrame& golden, Route route) {
  const testing::SplitFrame frame = testing::split_frame(golden);
  ASSERT_TRUE(frame.ok) << frame.problem;
  EXPECT_EQ(frame.header.source, route.source);
  EXPECT_EQ(frame.header.destination, route.destination);

  // The catalogue knows the id under the golden entry's name and section.
  const MessageInfo* info = find_message(frame.header.message_id);
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(std::string(info->name), golden.name);
  EXPECT_EQ(std::string(info->section), golden.section);
  if constexpr (!std::is_same_v<T, PlainAck>) {
    EXPECT_EQ(frame.payload.size(), T::kSize);
  }

  // Document bytes -> typed decode (of T's id) -> the expected fields.
  EXPECT_TRUE(fields_match(record_fields(decode_golden<T>(golden)), golden.expected));

  // The same through the catalogue's type-erased decoder.
  testing::expect_describes_to_expected(golden);

  // Expected values -> typed encode -> the hand-written bytes.
  T built{};
  ASSERT_TRUE(assign_fields(built, golden.expected));
  expect_encodes_to(built, golden);
}

struct TypedCase {
  const char* name;
  void (*check)(const GoldenFrame&, Route);
  Route route;
};

const std::vector<TypedCase>& typed_cases() {
  static const std::vector<TypedCase> cases = {
      {"camera_system_status", &check_golden<CameraSystemStatus>, kFromCamera},
      {"camera_upgrade_status", &check_golden<CameraUpgradeStatus>, kFromCamera},
      {"capture_mode", &check_golden<CaptureModeRequest>, kToCamera},
      {"capture_mode_ack", &check_golden<PlainAck>, kFromCamera},
      {"photo_settings", &check_golden<PhotoSettingsRequest>, kToCamera},
      {"take_photo", &check_golden<TakePhotoRequest>, kToCamera},
      {"take_photo_ack", &check_golden<PlainAck>, kFromCamera},
      {"record", &check_golden<RecordRequest>, kToCamera},
      {"zoom_ratio", &check_golden<ZoomRatioRequest>, kToCamera},
      {"continuous_zoom", &check_golden<ContinuousZoomRequest>, kToCamera},
      {"precise_reshoot", &check_golden<PreciseReshootRequest>, kToCamera},
      {"stream_bitrate", &check_golden<StreamBitrateRequest>, kToCamera},
      {"stream_resolution", &check_golden<StreamResolutionRequest>, kToCamera},
      {"stream_encoding", &check_golden<StreamEncodingRequest>, kToCamera},
      {"tf_card_upgrade", &check_golden<TfCardUpgradeRequest>, kToCamera},
      {"format_sd", &check_golden<FormatSdRequest>, kToCamera},
      {"time_sync", &check_golden<TimeSyncRequest>, kToCamera},
      {"factory_reset", &check_golden<FactoryResetRequest>, kToCamera},
      {"camera_gps_request", &check_golden<CameraGpsRequest>, kCameraToFlightController},
      {"camera_gps_request_ack", &check_golden<CameraGpsAck>, kFlightControllerToCamera},
      {"set_ip", &check_golden<SetIpRequest>, kToCamera},
      {"get_ip", &check_golden<GetIpRequest>, kToCamera},
      {"get_ip_ack", &check_golden<GetIpAck>, kFromCamera},
      {"focus", &check_golden<FocusRequest>, kToCamera},
      {"osd_watermark", &check_golden<OsdWatermarkRequest>, kToCamera},
      {"shutdown", &check_golden<ShutdownRequest>, kToCamera},
      {"camera_version", &check_golden<CameraVersionRequest>, kToCamera},
      {"camera_version_ack", &check_golden<CameraVersionAck>, kFromCamera},
      {"image_mode", &check_golden<ImageModeRequest>, kToCamera},
      {"ai_recognition", &check_golden<AiRecognitionRequest>, kToCamera},
      {"target_gps_request", &check_golden<TargetGpsRequest>, kFlightControllerToCamera},
      {"target_gps_request_ack", &check_golden<TargetGpsAck>, kCameraToFlightController},
      {"box_tracking", &check_golden<BoxTrackingRequest>, kToCamera},
      {"photo_status", &check_golden<PhotoStatus>, kFromCamera},
      {"record_status", &check_golden<RecordStatus>, kFromCamera},
      {"zoom_status", &check_golden<ZoomStatus>, kFromCamera},
      {"precise_reshoot_status", &check_golden<PreciseReshootStatus>, kFromCamera},
      {"tf_card_upgrade_status", &check_golden<TfCardUpgradeStatus>, kFromCamera},
      {"sd_format_status", &check_golden<SdFormatStatus>, kFromCamera},
  };
  return cases;
}

TEST(CameraGolden, EveryFrameDecodesToItsFieldsAndEncodesBackToItsBytes) {
  const std::vector<GoldenFrame> golden = testing::load_golden(kFile);
  ASSERT_FALSE(golden.empty());
  std::set<std::string> seen;
  for (const GoldenFrame& frame : golden) {
    SCOPED_TRACE(frame.where() + " " + frame.name);
    EXPECT_TRUE(seen.insert(frame.name).second) << "two entries named " << frame.name;
    const TypedCase* typed = nullptr;
    for (const TypedCase& c : typed_cases()) {
      if (frame.name == c.name) typed = &c;
    }
    ASSERT_NE(typed, nullptr) << "no typed check for golden entry " << frame.name;
    typed->check(frame, typed->route);
  }
  EXPECT_EQ(seen.size(), typed_cases().size()) << "a typed case has no golden frame";
}

bool in_camera_family(MessageId id) {
  const MessageId request = request_id_of(id);
  return request == 0x0003 || request == 0x0008 || (request >= 0x0300 && request <= 0x03FF);
}

// Every id this family registers has a hand-written frame; of the ACKs that are the bare
// response code, at least one does.
TEST(CameraGolden, CoversEveryCameraMessageOfTheCatalogue) {
  std::set<std::string> golden_names;
  for (const GoldenFrame& frame : testing::load_golden(kFile)) golden_names.insert(frame.name);
  int plain_acks = 0;
  int covered = 0;
  for (const MessageInfo& info : catalogue()) {
    if (!in_camera_family(info.id)) continue;
    const bool has_frame = golden_names.count(info.name) > 0;
    if (info.describe == &describe_payload<PlainAck>) {
      plain_acks += has_frame ? 1 : 0;
      continue;
    }
    EXPECT_TRUE(has_frame) << "no golden frame for " << info.name;
    ++covered;
  }
  EXPECT_GE(plain_acks, 1);
  EXPECT_EQ(covered, 37);  // 2 reports + 25 requests + 2 flight-controller requests + 4 data ACKs +
                           // 6 status frames
}

// A few requests built field by field in C++ rather than from the file's "=" lines.
GoldenFrame golden(const char* name) {
  return testing::golden(kFile, name);
}

TEST(CameraGolden, TakePhotoBuiltInCode) {
  TakePhotoRequest m;
  m.lens = PhotoLensMode::kVisible;
  m.action = PhotoAction::kStart;
  m.folder = "survey";
  m.name = "img_0001";
  expect_encodes_to(m, golden("take_photo"));
}

TEST(CameraGolden, RecordWithFullWidthTextsBuiltInCode) {
  RecordRequest m;
  m.lens = RecordLensMode::kStreamCapture;
  m.action = RecordAction::kStart;
  m.folder = "flight_2024_06_01_ab";            // 20 bytes
  m.name = "thermal_inspection_line_07_pass2";  // 32 bytes
  expect_encodes_to(m, golden("record"));
}

TEST(CameraGolden, TimeSyncBuiltInCode) {
  TimeSyncRequest m;
  m.unix_time_ms = 1718000000123;
  m.tz_minutes_west = -480;
  m.tz_dst_type = 0;
  expect_encodes_to(m, golden("time_sync"));
}

TEST(CameraGolden, SetIpBuiltInCode) {
  expect_encodes_to(message_from_text<SetIpRequest>("mode=static address=192.168.144.100 "
                                                    "netmask=255.255.255.0 gateway=192.168.144.1"),
                    golden("set_ip"));
}

TEST(CameraGolden, GpsAnswerBuiltInCodeEchoesTheRequestTime) {
  CameraGpsAck m = CameraGpsAck::answering(
      message_from_text<CameraGpsRequest>("hour=14 minute=35 second=12 millisecond=250"));
  set_fields(m,
             "longitude_deg=113.9465432 latitude_deg=22.5401234 relative_height_m=120.5 "
             "altitude_m=156.3 yaw_deg=-45.25 roll_deg=1.5 pitch_deg=-2.75");
  expect_encodes_to(m, golden("camera_gps_request_ack"));
}

TEST(CameraGolden, TargetGpsRequestBuiltInCode) {
  expect_encodes_to(
      message_from_text<TargetGpsRequest>(
          "mount_mask=0x01 fix=rtk_fixed utc_time_ms=1718000000123 longitude_deg=113.9465432 "
          "latitude_deg=22.5401234 relative_height_m=120.512 altitude_m=156.3 yaw_deg=-45.25 "
          "roll_deg=1.5 pitch_deg=-2.75 airspeed_m_s=12.34 ground_speed_m_s=11.5 "
          "heading_deg=314.75 throttle_percent=55 climb_rate_m_s=-1.2"),
      golden("target_gps_request"));
}

TEST(CameraGolden, BoxTrackingBuiltInCode) {
  expect_encodes_to(message_from_text<BoxTrackingRequest>(
                        "tracking=on x_px=860 y_px=440 width_px=200 height_px=200"),
                    golden("box_tracking"));
}

}  // namespace
}  // namespace k40t::protocol
