// cfg/setting_enums.txt, the one list of the enumerated settings' names that cfg/K40t.cfg builds
// its constants from and the build turns into the protocol's to_string() tables
// (cmake/cfg_enum_names.cmake), against the C++ code that still names or takes the same codes:
// every code is one the protocol knows (to_string), the names are the protocol's, the simulator's
// palettes are the same 20 under the same names, and every setting request that takes an enum has
// its list.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "k40t_driver/protocol/messages/camera_enums.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "k40t_driver/sim/video/palette.h"

namespace k40t::protocol {
namespace {

struct Item {
  int code;
  std::string constant;
};

// parameter -> its items, in file order.
std::map<std::string, std::vector<Item>> read_enums() {
  std::ifstream in(std::string(K40T_TEST_DATA_DIR) + "/../../cfg/setting_enums.txt");
  EXPECT_TRUE(in) << "cfg/setting_enums.txt not found";
  std::map<std::string, std::vector<Item>> enums;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string first, second, third;
    if (!(words >> first >> second)) continue;
    if (first == "enum") {
      enums[second];
      continue;
    }
    EXPECT_TRUE(words >> third) << line;
    EXPECT_EQ(enums.count(first), 1u) << "item before its 'enum' line: " << line;
    enums[first].push_back({std::stoi(second, nullptr, 0), third});
  }
  return enums;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Every code of `parameter` is one the protocol's enum E knows; with a prefix, every constant is
// prefix + the protocol's name of its code.
template <class E>
void expect_protocol_codes(const std::string& parameter, const std::string& prefix = "") {
  const auto enums = read_enums();
  ASSERT_EQ(enums.count(parameter), 1u) << parameter << " has no list";
  ASSERT_FALSE(enums.at(parameter).empty()) << parameter;
  for (const Item& item : enums.at(parameter)) {
    const char* name = to_string(static_cast<E>(item.code));
    ASSERT_NE(name, nullptr) << parameter << " code " << item.code << " is not a protocol code";
    if (!prefix.empty()) {
      EXPECT_EQ(item.constant, prefix + lower(name)) << parameter;
    }
  }
}

TEST(SettingEnums, NamesAreTheProtocols) {
  expect_protocol_codes<Palette>("palette", "palette_");
  expect_protocol_codes<WhiteBalance>("white_balance", "wb_");
  expect_protocol_codes<AntiFlicker>("anti_flicker", "flicker_");
  expect_protocol_codes<ThermalGainMode>("thermal_gain", "gain_");
  expect_protocol_codes<CaptureMode>("camera_mode", "mode_");
  expect_protocol_codes<VideoEncoding>("stream_encoding", "encoding_");
}

TEST(SettingEnums, CodesAreTheProtocols) {
  expect_protocol_codes<ImageMode>("image_mode");
  expect_protocol_codes<PhotoMode>("photo_mode");
  expect_protocol_codes<VideoResolution>("video_resolution");
  expect_protocol_codes<PhotoResolution>("photo_resolution");
  expect_protocol_codes<Iso>("iso");
  expect_protocol_codes<Shutter>("shutter");
  expect_protocol_codes<ExposureValue>("ev");
  expect_protocol_codes<MeteringMode>("metering");
  expect_protocol_codes<StreamBitrate>("stream_bitrate");
  expect_protocol_codes<StreamResolution>("stream_resolution");
}

TEST(SettingEnums, EveryProtocolPaletteIsListedAndTheSimulatorDrawsEach) {
  const auto palettes = read_enums().at("palette");
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
