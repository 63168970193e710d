// The outcome of a scripted exchange with the payload: one line per check.
#pragma once

#include <string>
#include <vector>

namespace k40t::psdk::sim {

struct CheckItem {
  std::string name;
  bool passed = false;
  std::string detail;  // what was sent, what came back
};

struct CheckReport {
  std::vector<CheckItem> items;

  void add(std::string name, bool passed, std::string detail) {
    items.push_back({std::move(name), passed, std::move(detail)});
  }
  bool passed() const {
    for (const CheckItem& i : items) {
      if (!i.passed) return false;
    }
    return !items.empty();
  }
  size_t failures() const {
    size_t n = 0;
    for (const CheckItem& i : items) n += i.passed ? 0 : 1;
    return n;
  }
  // "PASS get_gimbal_state: ..." lines.
  std::string summary() const {
    std::string out;
    for (const CheckItem& i : items)
      out += std::string(i.passed ? "PASS " : "FAIL ") + i.name + ": " + i.detail + "\n";
    return out;
  }
};

}  // namespace k40t::psdk::sim
