// A FieldSink that puts "<group><n>_" before every name, for the repeated entries of
// variable-length commands (widget3_value, point1_longitude_deg). The names it passes on live
// only for the duration of each call, like every FieldSink name should be treated.
#pragma once

#include <string>

#include "k40t_driver/codec/field_visit.h"

namespace k40t::psdk {

class IndexedSink : public codec::FieldSink {
 public:
  // `number` is shown as is (callers count from 1 for humans).
  IndexedSink(codec::FieldSink& inner, const char* group, size_t number)
      : inner_(inner), prefix_(std::string(group) + std::to_string(number) + "_") {}

  void integer(const char* name, int64_t value) override {
    inner_.integer(full(name).c_str(), value);
  }
  void unsigned_integer(const char* name, uint64_t value) override {
    inner_.unsigned_integer(full(name).c_str(), value);
  }
  void real(const char* name, double value) override { inner_.real(full(name).c_str(), value); }
  void boolean(const char* name, bool value) override { inner_.boolean(full(name).c_str(), value); }
  void text(const char* name, const std::string& value) override {
    inner_.text(full(name).c_str(), value);
  }
  void enumeration(const char* name, int64_t code, const char* label) override {
    inner_.enumeration(full(name).c_str(), code, label);
  }
  void bytes(const char* name, const uint8_t* data, size_t size) override {
    inner_.bytes(full(name).c_str(), data, size);
  }

 private:
  std::string full(const char* name) const { return prefix_ + name; }
  codec::FieldSink& inner_;
  std::string prefix_;
};

}  // namespace k40t::psdk
