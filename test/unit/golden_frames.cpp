#include "golden_frames.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>

namespace k40t::test {

namespace {

bool is_blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

Result<std::vector<uint8_t>> parse_hex_line(const std::string& line) {
  std::vector<uint8_t> bytes;
  std::istringstream in(line);
  std::string token;
  while (in >> token) {
    if (token.size() != 2 || !std::isxdigit(static_cast<unsigned char>(token[0])) ||
        !std::isxdigit(static_cast<unsigned char>(token[1]))) {
      return Result<std::vector<uint8_t>>::fail("'" + token +
                                                "' is not a hex byte (two hex digits)");
    }
    bytes.push_back(static_cast<uint8_t>(std::stoul(token, nullptr, 16)));
  }
  return bytes;
}

// `name=value name="quoted value" ...`
Result<protocol::FieldArgs> parse_expected(const std::string& text) {
  protocol::FieldArgs args;
  size_t i = 0;
  while (true) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i >= text.size()) break;
    const size_t equals = text.find('=', i);
    const size_t space = text.find_first_of(" \t", i);
    if (equals == std::string::npos || (space != std::string::npos && space < equals) ||
        equals == i) {
      return Result<protocol::FieldArgs>::fail("expected name=value at '" + text.substr(i) + "'");
    }
    const std::string name = text.substr(i, equals - i);
    std::string value;
    i = equals + 1;
    if (i < text.size() && text[i] == '"') {
      const size_t close = text.find('"', i + 1);
      if (close == std::string::npos)
        return Result<protocol::FieldArgs>::fail("unterminated quote in '" + name + "'");
      value = text.substr(i + 1, close - i - 1);
      i = close + 1;
    } else {
      const size_t end = text.find_first_of(" \t\r", i);
      value = text.substr(i, end == std::string::npos ? std::string::npos : end - i);
      i = end == std::string::npos ? text.size() : end;
    }
    if (!args.emplace(name, value).second)
      return Result<protocol::FieldArgs>::fail("field '" + name + "' given twice");
  }
  return args;
}

}  // namespace

Result<std::vector<GoldenFrame>> parse_golden_text(const std::string& text,
                                                   const std::string& name) {
  std::vector<GoldenFrame> frames;
  GoldenFrame current;
  bool in_frame = false;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  const auto fail = [&](const std::string& why) {
    return Result<std::vector<GoldenFrame>>::fail(name + ":" + std::to_string(number) + ": " + why);
  };
  while (std::getline(in, line)) {
    ++number;
    if (is_blank(line) || line[0] == '#') continue;
    if (line[0] == '=') {
      if (!in_frame) return fail("'=' line without the hex lines of a frame before it");
      Result<protocol::FieldArgs> expected = parse_expected(line.substr(1));
      if (!expected) return fail(expected.error());
      current.expected = std::move(expected.value());
      frames.push_back(std::move(current));
      current = GoldenFrame();
      in_frame = false;
      continue;
    }
    Result<std::vector<uint8_t>> bytes = parse_hex_line(line);
    if (!bytes) return fail(bytes.error());
    if (!in_frame) current.where = name + ":" + std::to_string(number);
    in_frame = true;
    current.bytes.insert(current.bytes.end(), bytes->begin(), bytes->end());
  }
  if (in_frame) return fail("the frame starting at " + current.where + " has no '=' line");
  if (frames.empty()) return fail("no frames");
  return frames;
}

Result<std::vector<GoldenFrame>> read_golden_file(const std::string& path) {
  std::ifstream file(path);
  if (!file) return Result<std::vector<GoldenFrame>>::fail("cannot read " + path);
  std::stringstream text;
  text << file.rdbuf();
  const size_t slash = path.find_last_of('/');
  return parse_golden_text(text.str(), slash == std::string::npos ? path : path.substr(slash + 1));
}

void DecodedFields::add(const char* name, Value v) {
  order_.emplace_back(name);
  fields_[name] = std::move(v);
}

void DecodedFields::integer(const char* name, int64_t value) {
  add(name, {Kind::kSigned, value, 0, 0, ""});
}

void DecodedFields::unsigned_integer(const char* name, uint64_t value) {
  add(name, {Kind::kUnsigned, 0, value, 0, ""});
}

void DecodedFields::real(const char* name, double value) {
  add(name, {Kind::kReal, 0, 0, value, ""});
}

void DecodedFields::boolean(const char* name, bool value) {
  add(name, {Kind::kBool, value ? 1 : 0, 0, 0, ""});
}

void DecodedFields::text(const char* name, const std::string& value) {
  add(name, {Kind::kText, 0, 0, 0, value});
}

void DecodedFields::enumeration(const char* name, int64_t code, const char* label) {
  add(name, {Kind::kEnum, code, 0, 0, label ? label : ""});
}

void DecodedFields::bytes(const char* name, const uint8_t* data, size_t size) {
  add(name, {Kind::kBytes, 0, 0, 0, std::string(data, data + size)});
}

Status DecodedFields::matches(const std::string& name, const std::string& expected) const {
  const auto found = fields_.find(name);
  if (found == fields_.end()) {
    std::string all;
    for (const std::string& n : order_) all += (all.empty() ? "" : ", ") + n;
    return Status::fail("no field '" + name + "' in the decoded message; its fields: " + all);
  }
  const Value& v = found->second;
  const char* n = name.c_str();
  const auto mismatch = [&](const std::string& decoded) {
    return Status::fail("field '" + name + "': expected " + expected + ", decoded " + decoded);
  };
  switch (v.kind) {
    case Kind::kSigned: {
      Result<int64_t> e = protocol::parse_signed_field(n, expected, INT64_MIN, INT64_MAX);
      if (!e) return e.status();
      return e.value() == v.i ? Status::ok() : mismatch(std::to_string(v.i));
    }
    case Kind::kUnsigned: {
      Result<uint64_t> e = protocol::parse_unsigned_field(n, expected, UINT64_MAX);
      if (!e) return e.status();
      return e.value() == v.u ? Status::ok() : mismatch(std::to_string(v.u));
    }
    case Kind::kReal: {
      Result<double> e = protocol::parse_real_field(n, expected);
      if (!e) return e.status();
      const double tolerance = 1e-9 * std::max(1.0, std::fabs(e.value()));
      std::ostringstream decoded;
      decoded.precision(17);
      decoded << v.d;
      return std::fabs(e.value() - v.d) <= tolerance ? Status::ok() : mismatch(decoded.str());
    }
    case Kind::kBool: {
      Result<bool> e = protocol::parse_bool_field(n, expected);
      if (!e) return e.status();
      return (e.value() ? 1 : 0) == v.i ? Status::ok() : mismatch(v.i ? "true" : "false");
    }
    case Kind::kText:
      return expected == v.text ? Status::ok() : mismatch("\"" + v.text + "\"");
    case Kind::kEnum: {
      const std::string decoded = std::to_string(v.i) + " (" + v.text + ")";
      if (!v.text.empty() &&
          protocol::normalize_label(expected) == protocol::normalize_label(v.text)) {
        return Status::ok();
      }
      Result<int64_t> e = protocol::parse_signed_field(n, expected, INT64_MIN, INT64_MAX);
      if (!e) return mismatch(decoded);
      return e.value() == v.i ? Status::ok() : mismatch(decoded);
    }
    case Kind::kBytes: {
      std::vector<uint8_t> e(v.text.size());
      const Status parsed = protocol::parse_bytes_field(n, expected, e.data(), e.size());
      std::string decoded;
      for (unsigned char c : v.text) decoded += (decoded.empty() ? "" : ",") + std::to_string(c);
      if (!parsed) return mismatch(decoded);
      const bool same = std::equal(e.begin(), e.end(), v.text.begin(), [](uint8_t a, char b) {
        return a == static_cast<unsigned char>(b);
      });
      return same ? Status::ok() : mismatch(decoded);
    }
  }
  return Status::fail("unreachable");
}

}  // namespace k40t::test
