// The cfg (cfg/K40t.cfg, as generated into K40tConfig) against cfg/setting_enums.txt as the
// protocol reads it (protocol/setting_enums.h, checked against the file by
// test/unit/test_setting_enums.cpp): every enum parameter offers exactly its list's entries that
// are not "protocol_only" (code, constant, description, in order), within its range, and its
// "protocol_only" codes lie outside that range; every list belongs to an enum parameter.
#include <gtest/gtest.h>

#include <boost/any.hpp>
#include <regex>
#include <string>
#include <vector>

#include <k40t_driver/K40tConfig.h>

#include "k40t_driver/protocol/setting_enums.h"

namespace k40t::protocol {
namespace {

using Config = k40t_driver::K40tConfig;

struct Constant {
  int value;
  std::string name;
  std::string description;
  bool operator==(const Constant& o) const {
    return value == o.value && name == o.name && description == o.description;
  }
};

std::ostream& operator<<(std::ostream& out, const Constant& c) {
  return out << c.value << " " << c.name << " '" << c.description << "'";
}

// dynamic_reconfigure keeps an enum as the Python repr of a dict: "{'enum': [{'name':
// 'palette_white_hot', 'type': 'int', 'value': 1, ..., 'description': 'white hot', ...}, ...]}".
std::vector<Constant> constants_of(const std::string& edit_method) {
  static const std::regex entry(
      R"(\{'name': '(\w+)', 'type': 'int', 'value': (-?\d+),[^{}]*'description': '([^']*)')");
  std::vector<Constant> constants;
  for (std::sregex_iterator it(edit_method.begin(), edit_method.end(), entry), end; it != end;
       ++it) {
    constants.push_back({std::stoi((*it)[2]), (*it)[1], (*it)[3]});
  }
  return constants;
}

int bound(const Config::AbstractParamDescriptionConstPtr& param, const Config& config) {
  boost::any value;
  param->getValue(config, value);
  return boost::any_cast<int>(value);
}

TEST(CfgEnums, EachEnumParameterOffersExactlyItsListsEntriesThatAreNotProtocolOnly) {
  size_t enum_parameters = 0;
  for (const auto& param : Config::__getParamDescriptions__()) {
    if (param->edit_method.empty()) continue;
    ++enum_parameters;
    SCOPED_TRACE(param->name);
    const SettingEnum* list = nullptr;
    for (const SettingEnum& l : setting_enums()) {
      if (param->name == l.parameter) list = &l;
    }
    ASSERT_NE(list, nullptr) << "an enum parameter with no list in cfg/setting_enums.txt";
    const int min = bound(param, Config::__getMin__());
    const int max = bound(param, Config::__getMax__());
    std::vector<Constant> offered;
    for (const SettingEnumName& name : *list) {
      const bool in_range = min <= name.code && name.code <= max;
      EXPECT_EQ(in_range, name.offered)
          << name.constant << " (" << name.code << ") " << (name.offered ? "outside" : "inside")
          << " the cfg's range " << min << ".." << max;
      if (name.offered) offered.push_back({name.code, name.constant, name.description});
    }
    EXPECT_EQ(constants_of(param->edit_method), offered);
  }
  EXPECT_EQ(enum_parameters, setting_enums().size()) << "a list with no enum parameter";
}

}  // namespace
}  // namespace k40t::protocol
