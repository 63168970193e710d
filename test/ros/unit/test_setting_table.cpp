// The settings table (settings_bindings.cpp) against what it must agree with: every cfg parameter
// of cfg/K40t.cfg belongs to exactly one entry and every entry to at least one parameter; each
// entry's request and report are catalogue messages; the read-back changes exactly the readable
// entries' parameters; the "reconfigure" column of docs/protocol/*.md is the one the entries give.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "../../unit/message_text.h"  // test/unit/message_text.h
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/ros/setting_binding.h"

namespace k40t::driver {
namespace {

using k40t::testing::message_from_text;

// The cfg parameters that are settings (all but the read-only last_refusal).
std::vector<std::string> cfg_parameters() {
  std::vector<std::string> names;
  for (const auto& param : Config::__getParamDescriptions__()) {
    if (param->name != kLastRefusalParameter) names.push_back(param->name);
  }
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
  protocol::ThermalSettingsAck thermal = message_from_text<protocol::ThermalSettingsAck>(
      "palette=iron_red zoom_x=3 measurement_on=false gain_mode=low sharpness=7 brightness=7 "
      "contrast=7 denoise_on=true enhancement_on=true denoise_level=9 enhancement_level=9 "
      "high_alarm_on=true low_alarm_on=true difference_alarm_on=true high_alarm_degC=33.0 "
      "low_alarm_degC=33.0 difference_alarm_degC=33.0 threshold_alarm_on=true "
      "threshold_reference_degC=11.0 threshold_float_degC=11.0");
  protocol::VisibleSettingsAck visible = message_from_text<protocol::VisibleSettingsAck>(
      "photo_resolution=8000x6000 video_resolution=3840x2160 white_balance=dusk iso=iso_800 "
      "shutter=1/500 backlight_on=true strong_light_on=true ae_lock_on=true watermark_on=true "
      "backlight_value=13 strong_light_value=13 anti_flicker=60hz metering=average");
  protocol::CameraSystemStatus camera = message_from_text<protocol::CameraSystemStatus>(
      "capture_mode=video stream_resolution=720p30 encoding=h265 image_mode=split "
      "bitrate=12_Mbit/s photo_mode=timelapse time_lapse_interval_s=30 burst_count=5");
  protocol::GimbalStatus gimbal;
  OddReports() {
    visible.ev = protocol::ExposureValue::kPlus2;  // by hand: "+2" and "-2" are both "2" as text
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

std::vector<std::string> cells_of(const std::string& row) {
  std::vector<std::string> cells;
  std::istringstream in(row.substr(1));  // after the leading '|'
  std::string cell;
  while (std::getline(in, cell, '|')) {
    const size_t first = cell.find_first_not_of(' ');
    cells.push_back(first == std::string::npos
                        ? ""
                        : cell.substr(first, cell.find_last_not_of(' ') - first + 1));
  }
  return cells;
}

// Message id (the row's first cell, "0x00010A") -> its "reconfigure" cell, for every row of the
// docs/protocol/*.md tables that have that column and whose cell is not empty; `where` gets each
// row's file:line.
std::map<std::string, std::string> docs_reconfigure_cells(
    std::map<std::string, std::string>* where) {
  std::map<std::string, std::string> cells;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(K40T_SOURCE_DIR) + "/docs/protocol")) {
    if (entry.path().extension() != ".md") continue;
    std::ifstream in(entry.path());
    std::string line;
    int column = -1;
    for (int number = 1; std::getline(in, line); ++number) {
      if (line.rfind("|", 0) != 0) {
        column = -1;  // a table ends at the first line that is not a row
        continue;
      }
      const std::vector<std::string> row = cells_of(line);
      if (row.empty()) continue;
      if (row[0] == "id") {
        column = -1;
        for (size_t i = 0; i < row.size(); ++i) {
          if (row[i].rfind("reconfigure", 0) == 0) column = static_cast<int>(i);
        }
      } else if (column >= 0 && row[0].rfind("0x", 0) == 0 &&
                 static_cast<int>(row.size()) > column && !row[column].empty()) {
        EXPECT_EQ(cells.count(row[0]), 0u) << row[0] << " has two reconfigure cells";
        cells[row[0]] = row[column];
        (*where)[row[0]] = entry.path().filename().string() + ":" + std::to_string(number);
      }
    }
  }
  return cells;
}

std::string hex_id(protocol::MessageId id) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%06X", static_cast<unsigned>(id));
  return hex;
}

// The docs name each setting once, in its request's row of docs/protocol/*.md: that cell is what
// the binding gives, and no row names a setting the table does not have.
TEST(SettingTable, DocsProtocolRowsAreTheOnesTheTableGives) {
  std::map<std::string, std::string> where;
  std::map<std::string, std::string> docs = docs_reconfigure_cells(&where);
  ASSERT_FALSE(docs.empty()) << "no reconfigure column in docs/protocol/*.md";
  for (const SettingBinding& binding : setting_bindings()) {
    const std::string id = hex_id(binding.request);
    if (docs.count(id) == 0) {
      ADD_FAILURE() << "docs/protocol/*.md: the row of " << id
                    << " needs this reconfigure cell: " << settings_docs_cell(binding);
      continue;
    }
    EXPECT_EQ(docs[id], settings_docs_cell(binding)) << where[id];
    docs.erase(id);
  }
  for (const auto& [id, cell] : docs) {
    ADD_FAILURE() << where[id] << ": a reconfigure cell for " << id << " but no setting sends it";
  }
}

}  // namespace
}  // namespace k40t::driver
