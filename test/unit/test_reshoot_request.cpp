// precise_reshoot's arguments in physical units -> 0x000307 (section 3.2.4.7): the zoom and the
// focal value default to the latest visible report (0x000005), the focal value goes back as the
// very uint16 the report carried, and bad arguments fail naming the field.
#include <gtest/gtest.h>

#include "k40t_driver/operations/camera_operations.h"

namespace k40t::driver {
namespace {

namespace p = protocol;
using operations::reshoot_request;
using operations::ReshootArgs;

ReshootArgs visible_4000x3000() {
  ReshootArgs args;
  args.lens = 2;
  args.resolution = 0x15;
  args.zoom_ratio = 12.5;
  args.focal_length_mm = 37.6;
  args.name = "pole_17";
  return args;
}

p::VisibleStatus report(double zoom_x, double precise_focal_mm) {
  p::VisibleStatus v;
  v.zoom_x = zoom_x;
  v.precise_shot_focal_length_mm = precise_focal_mm;
  return v;
}

TEST(ReshootRequest, ExplicitValuesAreSentAsGiven) {
  Result<p::PreciseReshootRequest> r = reshoot_request(visible_4000x3000(), std::nullopt);
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->lens, p::PhotoLensMode::kVisible);
  EXPECT_EQ(static_cast<int>(r->resolution), 0x15);
  EXPECT_DOUBLE_EQ(r->zoom_x, 12.5);
  EXPECT_EQ(r->focal_length_raw, 3760);  // 37.6 mm in the report's 0.01 mm
  EXPECT_EQ(r->name, "pole_17");
  // Bytes 5-6 low byte first: 3760 = 0x0EB0 -> B0 0E.
  Result<p::Payload> payload = p::encode_payload(r.value());
  ASSERT_TRUE(payload) << payload.error();
  EXPECT_EQ(payload->bytes[4], 0xB0);
  EXPECT_EQ(payload->bytes[5], 0x0E);
}

// Bytes 3-4 carry the ratio x10 (section 3.2.4.7): 2.34 goes out as 23 = 2.3, and the request (what
// precise_reshoot answers as "what was sent") says 2.3, not 2.34.
TEST(ReshootRequest, TheZoomIsTheOneTheWireCarries) {
  ReshootArgs args = visible_4000x3000();
  args.zoom_ratio = 2.34;
  Result<p::PreciseReshootRequest> r = reshoot_request(args, std::nullopt);
  ASSERT_TRUE(r) << r.error();
  EXPECT_DOUBLE_EQ(r->zoom_x, 2.3);
  Result<p::Payload> payload = p::encode_payload(r.value());
  ASSERT_TRUE(payload) << payload.error();
  EXPECT_EQ(payload->bytes[2], 23);
  EXPECT_EQ(payload->bytes[3], 0);
  args.zoom_ratio = 2.36;
  EXPECT_DOUBLE_EQ(reshoot_request(args, std::nullopt)->zoom_x, 2.4);
}

TEST(ReshootRequest, ZeroMeansTheLatestVisibleReport) {
  ReshootArgs args = visible_4000x3000();
  args.zoom_ratio = 0;
  args.focal_length_mm = 0;
  Result<p::PreciseReshootRequest> r = reshoot_request(args, report(8.0, 94.27));
  ASSERT_TRUE(r) << r.error();
  EXPECT_DOUBLE_EQ(r->zoom_x, 8.0);
  EXPECT_EQ(r->focal_length_raw, 9427);
}

TEST(ReshootRequest, ZeroWithoutAReportIsAnError) {
  ReshootArgs args = visible_4000x3000();
  args.focal_length_mm = 0;
  Result<p::PreciseReshootRequest> r = reshoot_request(args, std::nullopt);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("focal_length_mm"), std::string::npos) << r.error();
}

TEST(ReshootRequest, BadArgumentsNameTheField) {
  const struct {
    const char* field;
    void (*spoil)(ReshootArgs&);
  } cases[] = {
      {"resolution", [](ReshootArgs& a) { a.resolution = 0x18; }},
      {"lens", [](ReshootArgs& a) { a.lens = 4; }},
      {"zoom_ratio", [](ReshootArgs& a) { a.zoom_ratio = 161; }},
      {"focal_length_mm", [](ReshootArgs& a) { a.focal_length_mm = 700; }},
      {"focal_length_mm", [](ReshootArgs& a) { a.focal_length_mm = -1; }},
      {"name", [](ReshootArgs& a) { a.name = std::string(33, 'x'); }},
  };
  for (const auto& c : cases) {
    ReshootArgs args = visible_4000x3000();
    c.spoil(args);
    Result<p::PreciseReshootRequest> r = reshoot_request(args, report(1, 1));
    ASSERT_FALSE(r) << c.field;
    EXPECT_NE(r.error().find(c.field), std::string::npos) << r.error();
  }
}

}  // namespace
}  // namespace k40t::driver
