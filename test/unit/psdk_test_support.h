// Test helpers for the PSDK layer: a FieldSink that records "name=value" lines.
#pragma once

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "k40t_driver/protocol/field_visit.h"

namespace k40t::psdk::testing {

class RecordingSink : public protocol::FieldSink {
 public:
  std::vector<std::string> lines;

  void integer(const char* name, int64_t value) override { add(name, std::to_string(value)); }
  void unsigned_integer(const char* name, uint64_t value) override {
    add(name, std::to_string(value));
  }
  void real(const char* name, double value) override {
    std::ostringstream out;
    out << std::setprecision(17) << value;
    add(name, out.str());
  }
  void boolean(const char* name, bool value) override { add(name, value ? "true" : "false"); }
  void text(const char* name, const std::string& value) override { add(name, "\"" + value + "\""); }
  void enumeration(const char* name, int64_t code, const char* label) override {
    add(name, std::to_string(code) + "(" + (label ? label : "?") + ")");
  }
  void bytes(const char* name, const uint8_t* data, size_t size) override {
    std::ostringstream out;
    for (size_t i = 0; i < size; ++i)
      out << std::hex << std::setw(2) << std::setfill('0') << int(data[i]);
    add(name, out.str());
  }
  bool has(const std::string& line) const {
    for (const auto& l : lines) {
      if (l == line) return true;
    }
    return false;
  }

 private:
  void add(const char* name, const std::string& value) {
    lines.push_back(std::string(name) + "=" + value);
  }
};

}  // namespace k40t::psdk::testing
