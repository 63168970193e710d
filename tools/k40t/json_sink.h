// JSON output for `k40t decode`: a FieldSink that writes a message's fields as the members of one
// JSON object, and the small writer both use. Field names carry their units (yaw_deg, range_m).
#pragma once

#include <cstdint>
#include <string>

#include "k40t_driver/protocol/field_visit.h"

namespace k40t::tool {

// Appends JSON tokens to a string; members are separated automatically.
class JsonWriter {
 public:
  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  // Returns the writer, so that the value can follow in the same expression.
  JsonWriter& key(const char* name);
  void string(const std::string& value);
  void null();
  void boolean(bool value);
  void integer(int64_t value);
  void unsigned_integer(uint64_t value);
  void real(double value);
  // Convenience: key + value.
  void member(const char* name, const std::string& value) {
    key(name);
    string(value);
  }
  // A complete JSON value written elsewhere (a nested object), spliced in as the next value.
  void raw(const std::string& json) {
    separate();
    out_ += json;
  }
  const std::string& text() const { return out_; }

 private:
  void separate();
  void open(char bracket);
  void close(char bracket);
  std::string out_;
  bool need_comma_ = false;
};

std::string json_escape(const std::string& text);

// Writes each field as `"name": value`: enums as {"code": n, "name": "label"|null}, byte arrays
// as arrays of numbers.
class JsonFieldSink : public protocol::FieldSink {
 public:
  explicit JsonFieldSink(JsonWriter& out) : out_(out) {}
  void integer(const char* name, int64_t value) override { out_.key(name).integer(value); }
  void unsigned_integer(const char* name, uint64_t value) override {
    out_.key(name).unsigned_integer(value);
  }
  void real(const char* name, double value) override { out_.key(name).real(value); }
  void boolean(const char* name, bool value) override { out_.key(name).boolean(value); }
  void text(const char* name, const std::string& value) override { out_.member(name, value); }
  void enumeration(const char* name, int64_t code, const char* label) override;
  void bytes(const char* name, const uint8_t* data, size_t size) override;

 private:
  JsonWriter& out_;
};

}  // namespace k40t::tool
