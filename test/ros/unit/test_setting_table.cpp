// The settings table (settings_bindings.cpp) against what it must agree with: every cfg parameter
// of cfg/K40t.cfg belongs to exactly one entry and every entry to at least one parameter; each
// entry's request and report are catalogue messages; the read-back changes exactly the readable
// entries' parameters; the table in docs/ros_interface.md is the one the entries give.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/ros/setting_binding.h"

namespace k40t::driver {
namespace {

std::vector<std::string> cfg_parameters() {
  std::vector<std::string> names;
  for (const auto& param : Config::__getParamDescriptions__()) names.push_back(param->name);
  return names;
}

TEST(SettingTable, EveryCfgParameterHasExactlyOneBinding) {
  std::map<std::string, std::vector<std::string>> owners;
  for (const SettingBinding& binding : setting_bindings()) {
    for (const std::string& name : parameters_of(binding)) owners[name].push_back(binding.name);
  }
  ASSERT_FALSE(cfg_parameters().empty());
  for (const std::string& name : cfg_parameters()) {
    EXPECT_EQ(owners[name].size(), 1u)
        << "cfg parameter " << name << " is sent by " << owners[name].size() << " bindings";
  }
}

TEST(SettingTable, EveryBindingCoversACfgParameterAndNamesCatalogueMessages) {
  std::set<std::string> names;
  std::set<std::string> services;
  for (const SettingBinding& binding : setting_bindings()) {
    SCOPED_TRACE(binding.name);
    EXPECT_TRUE(names.insert(binding.name).second) << "two bindings share a name";
    EXPECT_FALSE(parameters_of(binding).empty()) << "a binding with no cfg parameter";
    const protocol::MessageInfo* request = protocol::find_message(binding.request);
    ASSERT_NE(request, nullptr);
    EXPECT_STREQ(request->name, binding.request_name);
    EXPECT_EQ(request->direction, protocol::Direction::kHostToPod);
    EXPECT_EQ(binding.readable(), static_cast<bool>(binding.read_back));
    if (binding.readable()) {
      EXPECT_NE(protocol::find_message(binding.read_from), nullptr);
    }
    if (!binding.service.empty()) {
      EXPECT_TRUE(services.insert(binding.service).second) << "a service writes two settings";
      EXPECT_EQ(binding_for_service(binding.service), &binding);
    }
  }
  EXPECT_EQ(binding_for_service("no_such_service"), nullptr);
  EXPECT_EQ(binding_for_service(""), nullptr);
}

// Reports whose every setting differs from the cfg defaults.
struct OddReports {
  protocol::ThermalSettingsAck thermal;
  protocol::VisibleSettingsAck visible;
  protocol::CameraSystemStatus camera;
  protocol::GimbalStatus gimbal;
  OddReports() {
    thermal.palette = protocol::Palette::kIronRed;
    thermal.zoom_x = 3;
    thermal.measurement_on = false;
    thermal.gain_mode = protocol::ThermalGainMode::kLow;
    thermal.sharpness = thermal.brightness = thermal.contrast = 7;
    thermal.denoise_on = thermal.enhancement_on = true;
    thermal.denoise_level = thermal.enhancement_level = 9;
    thermal.high_alarm_on = thermal.low_alarm_on = thermal.difference_alarm_on = true;
    thermal.high_alarm_degC = thermal.low_alarm_degC = thermal.difference_alarm_degC = 33.0;
    thermal.threshold_alarm_on = true;
    thermal.threshold_reference_degC = thermal.threshold_float_degC = 11.0;
    visible.photo_resolution = protocol::PhotoResolution::k8000x6000;
    visible.video_resolution = protocol::VideoResolution::k3840x2160;
    visible.white_balance = protocol::WhiteBalance::kDusk;
    visible.ev = protocol::ExposureValue::kPlus2;
    visible.iso = protocol::Iso::k800;
    visible.shutter = protocol::Shutter::k1_500;
    visible.backlight_on = visible.strong_light_on = visible.ae_lock_on = true;
    visible.watermark_on = true;
    visible.backlight_value = visible.strong_light_value = 13;
    visible.anti_flicker = protocol::AntiFlicker::k60Hz;
    visible.metering = protocol::MeteringMode::kAverage;
    camera.capture_mode = protocol::CaptureMode::kVideo;
    camera.stream_resolution = protocol::ReportedStreamResolution::k720p30;
    camera.encoding = protocol::VideoEncoding::kH265;
    camera.image_mode = protocol::ImageMode::kSplit;
    camera.bitrate = protocol::StreamBitrate::k12Mbps;
    camera.photo_mode = protocol::PhotoMode::kTimeLapse;
    camera.time_lapse_interval_s = 30;
    camera.burst_count = 5;
    gimbal.stabilisation = protocol::GimbalStabilisationState::kStabilising;
  }
  SettingReports all() const { return {&thermal, &visible, &camera, &gimbal}; }
};

TEST(SettingTable, ReadBackSetsTheReadableBindingsParametersAndNoOthers) {
  const OddReports reports;
  const Config before = Config::__getDefault__();
  Config after = before;
  absorb(after, reports.all());
  for (const SettingBinding& binding : setting_bindings()) {
    SCOPED_TRACE(binding.name);
    Config only_this = before;
    binding.copy(only_this, after);
    EXPECT_EQ(binding.differs(only_this, before), binding.readable())
        << (binding.readable() ? "the report did not change it" : "a write-only setting changed");
  }
  Config nothing = before;
  absorb(nothing, SettingReports{});  // no report arrived: nothing changes
  for (const SettingBinding& binding : setting_bindings()) {
    EXPECT_FALSE(binding.differs(nothing, before)) << binding.name;
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SettingTable, DocsTableIsTheOneTheTableGives) {
  const std::string doc = read_file(std::string(K40T_SOURCE_DIR) + "/docs/ros_interface.md");
  const std::string begin =
      "<!-- settings table begin: generated by settings_table_markdown() -->\n";
  const std::string end = "<!-- settings table end -->";
  const size_t from = doc.find(begin);
  const size_t to = doc.find(end);
  ASSERT_NE(from, std::string::npos) << "docs/ros_interface.md has no settings table";
  ASSERT_NE(to, std::string::npos);
  EXPECT_EQ(doc.substr(from + begin.size(), to - from - begin.size()), settings_table_markdown())
      << "paste this table into docs/ros_interface.md:\n"
      << settings_table_markdown();
}

}  // namespace
}  // namespace k40t::driver
