#include "k40t_driver/protocol/setting_enums.h"

#include <iterator>

#include "k40t_driver/protocol/cfg_enum_names.h"

namespace k40t::protocol {

const std::vector<SettingEnum>& setting_enums() {
  static const std::vector<SettingEnum> lists(std::begin(cfg_enums::all), std::end(cfg_enums::all));
  return lists;
}

}  // namespace k40t::protocol
