// What is derived from the settings table (settings_bindings.cpp): look-ups, the read-back and
// the cfg parameters each entry covers.
#include "k40t_driver/ros/setting_binding.h"

#include <cstdio>
#include <sstream>

#include <dynamic_reconfigure/config_tools.h>

#include "k40t_driver/protocol/message_id.h"

namespace k40t::driver {

const SettingBinding* find_binding(const std::string& name) {
  for (const SettingBinding& binding : setting_bindings()) {
    if (binding.name == name) return &binding;
  }
  return nullptr;
}

const SettingBinding* binding_for_service(const std::string& service) {
  for (const SettingBinding& binding : setting_bindings()) {
    if (!service.empty() && binding.service == service) return &binding;
  }
  return nullptr;
}

void absorb(Config& config, const SettingReports& reports) {
  for (const SettingBinding& binding : setting_bindings()) {
    if (binding.readable()) binding.read_back(config, reports);
  }
}

namespace {

// Every parameter of `config` in the message form dynamic_reconfigure publishes (name -> text).
std::vector<std::pair<std::string, std::string>> values_of(const Config& config) {
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  std::vector<std::pair<std::string, std::string>> values;
  for (const auto& p : message.bools) values.emplace_back(p.name, std::to_string(p.value));
  for (const auto& p : message.ints) values.emplace_back(p.name, std::to_string(p.value));
  for (const auto& p : message.strs) values.emplace_back(p.name, p.value);
  for (const auto& p : message.doubles) values.emplace_back(p.name, std::to_string(p.value));
  return values;
}

// A configuration in which every parameter differs from the default one.
Config every_parameter_changed() {
  dynamic_reconfigure::Config message;
  Config::__getDefault__().__toMessage__(message);
  for (auto& p : message.bools) p.value = !p.value;
  for (auto& p : message.ints) p.value += 1;
  for (auto& p : message.strs) p.value += "x";
  for (auto& p : message.doubles) p.value += 1.0;
  Config changed = Config::__getDefault__();
  changed.__fromMessage__(message);
  return changed;
}

}  // namespace

std::vector<std::string> parameters_of(const SettingBinding& binding) {
  const Config base = Config::__getDefault__();
  Config copied = base;
  binding.copy(copied, every_parameter_changed());
  const auto before = values_of(base);
  const auto after = values_of(copied);
  std::vector<std::string> names;
  for (const auto& param : Config::__getParamDescriptions__()) {
    for (size_t i = 0; i < before.size(); ++i) {
      if (before[i].first == param->name && before[i] != after[i]) names.push_back(param->name);
    }
  }
  return names;
}

namespace {

// The value of parameter `name` in `params` (the ints or doubles of a message), or nullptr.
template <class Param>
const Param* param_named(const std::vector<Param>& params, const std::string& name) {
  for (const Param& p : params) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

template <class Param>
void add_if_outside(std::string& out, const std::string& name, const std::vector<Param>& next,
                    const std::vector<Param>& current, const std::vector<Param>& lo,
                    const std::vector<Param>& hi) {
  const Param* n = param_named(next, name);
  const Param* c = param_named(current, name);
  const Param* l = param_named(lo, name);
  const Param* h = param_named(hi, name);
  if (!n || !c || !l || !h || n->value == c->value) return;
  if (l->value <= n->value && n->value <= h->value) return;
  std::ostringstream text;
  text << name << " " << n->value << " is outside " << l->value << ".." << h->value;
  out += (out.empty() ? "" : "; ") + text.str();
}

}  // namespace

std::string outside_cfg_range(const Config& next, const Config& current,
                              const std::vector<std::string>& names) {
  dynamic_reconfigure::Config n, c, lo, hi;
  next.__toMessage__(n);
  current.__toMessage__(c);
  Config::__getMin__().__toMessage__(lo);
  Config::__getMax__().__toMessage__(hi);
  std::string out;
  for (const std::string& name : names) {
    add_if_outside(out, name, n.ints, c.ints, lo.ints, hi.ints);
    add_if_outside(out, name, n.doubles, c.doubles, lo.doubles, hi.doubles);
  }
  return out;
}

namespace {

std::string hex_id(protocol::MessageId id) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%06X", static_cast<unsigned>(id));
  return hex;
}

}  // namespace

std::string settings_docs_cell(const SettingBinding& binding) {
  std::string cell;
  for (const std::string& name : parameters_of(binding)) {
    cell += (cell.empty() ? "`" : ", `") + name + "`";
  }
  cell += binding.readable() ? "; read back from " + hex_id(binding.read_from) : "; write-only";
  if (!binding.service.empty()) cell += "; service `" + binding.service + "`";
  return cell;
}

}  // namespace k40t::driver
