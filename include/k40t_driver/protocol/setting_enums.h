// The names of the enumerated pod settings as cfg/setting_enums.txt gives them, the one list that
// cfg/K40t.cfg builds its constants from and the build turns into tables
// (cmake/cfg_enum_names.cmake): the protocol's to_string() of those enums reads them, and tests
// hold the file and the generated cfg to them.
#pragma once

#include <cstddef>
#include <vector>

namespace k40t::protocol {

struct SettingEnumName {
  int code;                 // the byte the pod takes
  const char* constant;     // the dynamic_reconfigure constant: "palette_iron_red"
  const char* description;  // the constant's description: "iron red"
  bool offered;             // false: a "protocol_only" code, one the cfg does not offer
};

// One enumerated cfg parameter's names, in the list's order.
struct SettingEnum {
  const char* parameter;  // "palette"
  const SettingEnumName* names;
  size_t size;

  const SettingEnumName* begin() const { return names; }
  const SettingEnumName* end() const { return names + size; }
};

// Every enum of cfg/setting_enums.txt, in the file's order.
const std::vector<SettingEnum>& setting_enums();

}  // namespace k40t::protocol
