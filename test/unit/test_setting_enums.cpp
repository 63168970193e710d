// cfg/setting_enums.txt, the one list of the enumerated settings' names: the tables the build
// generates from it (protocol/setting_enums.h, cmake/cfg_enum_names.cmake) are the file,
// "protocol_only" marks included; the protocol's to_string() of every enum of the list names
// exactly the list's codes, with the list's names; the simulator's palettes are the same 20 under
// the same names. That the cfg offers exactly the entries that are not "protocol_only" is checked
// against the generated K40tConfig by test/ros/unit/test_cfg_enums.cpp.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "k40t_driver/protocol/messages/camera_enums.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "k40t_driver/protocol/setting_enums.h"
#include "k40t_driver/sim/video/palette.h"

namespace k40t::protocol {
namespace {

struct Item {
  int code;
  std::string constant;
  std::string description;
  bool offered;
};

struct List {
  std::string parameter;
  std::vector<Item> items;
};

// The file as the format at its top describes it, read without the build's generator.
std::vector<List> read_file() {
  std::ifstream in(std::string(K40T_TEST_DATA_DIR) + "/../../cfg/setting_enums.txt");
  EXPECT_TRUE(in) << "cfg/setting_enums.txt not found";
  std::vector<List> lists;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string first;
    if (!(words >> first)) continue;
    if (first == "enum") {
      lists.push_back({});
      words >> lists.back().parameter;
      continue;
    }
    const bool offered = first != "protocol_only";
    std::string parameter = first, code, constant, description;
    if (!offered) words >> parameter;
    EXPECT_TRUE(words >> code >> constant && std::getline(words >> std::ws, description)) << line;
    EXPECT_TRUE(!lists.empty() && lists.back().parameter == parameter)
        << "not under its enum: " << line;
    if (lists.empty()) continue;
    description.erase(description.find_last_not_of(" \t") + 1);
    lists.back().items.push_back({std::stoi(code, nullptr, 0), constant, description, offered});
  }
  return lists;
}

TEST(SettingEnums, GeneratedTablesAreTheFile) {
  const std::vector<List> file = read_file();
  const std::vector<SettingEnum>& tables = setting_enums();
  ASSERT_EQ(tables.size(), file.size());
  for (size_t i = 0; i < file.size(); ++i) {
    SCOPED_TRACE(file[i].parameter);
    EXPECT_EQ(tables[i].parameter, file[i].parameter);
    ASSERT_EQ(tables[i].size, file[i].items.size());
    for (size_t j = 0; j < file[i].items.size(); ++j) {
      const Item& item = file[i].items[j];
      EXPECT_EQ(tables[i].names[j].code, item.code);
      EXPECT_EQ(tables[i].names[j].constant, item.constant);
      EXPECT_EQ(tables[i].names[j].description, item.description);
      EXPECT_EQ(tables[i].names[j].offered, item.offered) << item.constant;
    }
  }
}

// One protocol enum read from a list: to_string() of every byte, and the column it names a code
// by: the constant without `prefix`, or (no prefix) the description.
struct NamedBy {
  const char* parameter;
  std::function<const char*(int)> name;
  std::string prefix;
};

template <class E>
std::function<const char*(int)> name_of() {
  return [](int code) { return to_string(static_cast<E>(code)); };
}

const std::vector<NamedBy>& named_enums() {
  static const std::vector<NamedBy> enums = {
      {"image_mode", name_of<ImageMode>(), "image_"},
      {"camera_mode", name_of<CaptureMode>(), "mode_"},
      {"photo_mode", name_of<PhotoMode>(), "photo_"},
      {"palette", name_of<Palette>(), "palette_"},
      {"thermal_gain", name_of<ThermalGainMode>(), "gain_"},
      {"video_resolution", name_of<VideoResolution>(), ""},
      {"photo_resolution", name_of<PhotoResolution>(), ""},
      {"iso", name_of<Iso>(), ""},
      {"shutter", name_of<Shutter>(), ""},
      {"ev", name_of<ExposureValue>(), ""},
      {"white_balance", name_of<WhiteBalance>(), "wb_"},
      {"anti_flicker", name_of<AntiFlicker>(), "flicker_"},
      {"metering", name_of<MeteringMode>(), "metering_"},
      {"stream_bitrate", name_of<StreamBitrate>(), ""},
      {"stream_resolution", name_of<StreamResolution>(), "stream_"},
      {"stream_encoding", name_of<VideoEncoding>(), ""},
  };
  return enums;
}

// The lists whose codes are plain numbers of a request (0x000301's interval and burst size), with
// no protocol enum to name them.
const std::set<std::string> kPlainNumbers = {"timelapse_interval", "burst_count"};

TEST(SettingEnums, ToStringNamesExactlyTheListsCodesByTheListsNames) {
  std::set<std::string> named;
  for (const NamedBy& e : named_enums()) {
    SCOPED_TRACE(e.parameter);
    named.insert(e.parameter);
    const SettingEnum* list = nullptr;
    for (const SettingEnum& l : setting_enums()) {
      if (l.parameter == std::string(e.parameter)) list = &l;
    }
    ASSERT_NE(list, nullptr) << "no list";
    std::vector<std::string> expected(256);
    for (const SettingEnumName& item : *list) {
      const std::string constant = item.constant;
      ASSERT_EQ(constant.rfind(e.prefix, 0), 0u) << constant << " does not start with " << e.prefix;
      expected.at(item.code) =
          e.prefix.empty() ? item.description : constant.substr(e.prefix.size());
    }
    for (int code = 0; code <= 255; ++code) {
      const char* name = e.name(code);
      EXPECT_EQ(name ? name : "", expected[code]) << "code " << code;
    }
  }
  for (const SettingEnum& list : setting_enums()) {
    EXPECT_TRUE(named.count(list.parameter) || kPlainNumbers.count(list.parameter))
        << list.parameter << ": a list no to_string() reads";
  }
}

TEST(SettingEnums, EveryProtocolPaletteIsListedAndTheSimulatorDrawsEach) {
  std::vector<Item> palettes;
  for (const List& list : read_file()) {
    if (list.parameter == "palette") palettes = list.items;
  }
  std::vector<int> codes;
  for (int code = 0; code <= 255; ++code) {
    if (to_string(static_cast<Palette>(code))) codes.push_back(code);
  }
  ASSERT_EQ(palettes.size(), codes.size());
  for (size_t i = 0; i < codes.size(); ++i) EXPECT_EQ(palettes[i].code, codes[i]);
  EXPECT_EQ(sim::video::kFirstPalette, codes.front());
  EXPECT_EQ(sim::video::kLastPalette, codes.back());
  for (const Item& item : palettes) {
    const auto name = sim::video::palette_name(item.code);
    ASSERT_TRUE(name) << name.error();
    EXPECT_EQ("palette_" + *name, item.constant);
  }
}

}  // namespace
}  // namespace k40t::protocol
