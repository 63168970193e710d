#include "json_sink.h"

#include <cmath>
#include <cstdio>

namespace k40t::tool {

std::string json_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size() + 2);
  for (unsigned char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c < 0x20 || c >= 0x7F) {  // control bytes, and bytes that may not be valid UTF-8
          char buffer[8];
          std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
          out += buffer;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out;
}

void JsonWriter::separate() {
  if (need_comma_) out_ += ',';
  need_comma_ = true;
}

void JsonWriter::open(char bracket) {
  separate();
  out_ += bracket;
  need_comma_ = false;
}

void JsonWriter::close(char bracket) {
  out_ += bracket;
  need_comma_ = true;
}

JsonWriter& JsonWriter::key(const char* name) {
  separate();
  out_ += '"';
  out_ += json_escape(name);
  out_ += "\":";
  need_comma_ = false;  // the value follows without a comma
  return *this;
}

void JsonWriter::string(const std::string& value) {
  separate();
  out_ += '"';
  out_ += json_escape(value);
  out_ += '"';
}

void JsonWriter::null() {
  separate();
  out_ += "null";
}

void JsonWriter::boolean(bool value) {
  separate();
  out_ += value ? "true" : "false";
}

void JsonWriter::integer(int64_t value) {
  separate();
  out_ += std::to_string(value);
}

void JsonWriter::unsigned_integer(uint64_t value) {
  separate();
  out_ += std::to_string(value);
}

void JsonWriter::real(double value) {
  separate();
  if (!std::isfinite(value)) {
    out_ += "null";  // JSON has no NaN or infinity
    return;
  }
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.10g", value);
  out_ += buffer;
}

void JsonFieldSink::enumeration(const char* name, int64_t code, const char* label) {
  out_.key(name);
  out_.begin_object();
  out_.key("code").integer(code);
  out_.key("name");
  if (label != nullptr) {
    out_.string(label);
  } else {
    out_.null();
  }
  out_.end_object();
}

void JsonFieldSink::bytes(const char* name, const uint8_t* data, size_t size) {
  out_.key(name);
  out_.begin_array();
  for (size_t i = 0; i < size; ++i) out_.unsigned_integer(data[i]);
  out_.end_array();
}

}  // namespace k40t::tool
