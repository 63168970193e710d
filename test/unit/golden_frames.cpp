#include "golden_frames.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "k40t_driver/protocol/parser.h"

namespace k40t::test {

namespace {

bool is_hex_token(const std::string& token) {
  return token.size() == 2 && std::isxdigit(static_cast<unsigned char>(token[0])) &&
         std::isxdigit(static_cast<unsigned char>(token[1]));
}

bool parse_number(const std::string& text, double* value) {
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

std::string format(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

GoldenFile load_golden_file(const std::string& name) {
  GoldenFile result;
  const std::string path = std::string(K40T_TEST_DATA_DIR) + "/golden/" + name;
  std::ifstream in(path);
  if (!in) {
    result.error = "cannot open " + path;
    return result;
  }
  std::string comment;
  GoldenFrame current;
  bool in_frame = false;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) {
      comment.clear();
      continue;
    }
    if (line[0] == '#') {
      comment += line + "\n";
      continue;
    }
    if (line[0] == '=') {
      if (!in_frame) {
        result.error = name + ":" + std::to_string(number) + ": '=' line without a frame";
        return result;
      }
      std::istringstream fields(line.substr(1));
      std::string pair;
      while (fields >> pair) {
        const size_t eq = pair.find('=');
        if (eq == std::string::npos || eq == 0) {
          result.error =
              name + ":" + std::to_string(number) + ": expected name=value, got '" + pair + "'";
          return result;
        }
        current.expected.emplace_back(pair.substr(0, eq), pair.substr(eq + 1));
      }
      result.frames.push_back(current);
      current = GoldenFrame{};
      in_frame = false;
      comment.clear();
      continue;
    }
    std::istringstream tokens(line);
    std::string token;
    if (!in_frame) {
      in_frame = true;
      current.file = name;
      current.line = number;
      current.comment = comment;
    }
    while (tokens >> token) {
      if (!is_hex_token(token)) {
        result.error = name + ":" + std::to_string(number) + ": not a hex byte: '" + token + "'";
        return result;
      }
      current.bytes.push_back(static_cast<uint8_t>(std::stoul(token, nullptr, 16)));
    }
  }
  if (in_frame)
    result.error = name + ":" + std::to_string(current.line) + ": frame without '=' line";
  return result;
}

ParsedFrame parse_golden_frame(const GoldenFrame& frame) {
  ParsedFrame parsed;
  int count = 0;
  protocol::FrameParser parser(protocol::CrcCoverage::kHeaderExcluded);
  parser.feed(frame.bytes.data(), frame.bytes.size(), [&](const protocol::FrameView& view) {
    ++count;
    parsed.header = view.header;
    parsed.payload.assign(view.payload, view.payload + view.payload_size);
    parsed.ok = view.size == frame.bytes.size();
  });
  if (count != 1 || !parsed.ok) {
    parsed.ok = false;
    parsed.error = frame.where() + ": the bytes are not exactly one valid frame (" +
                   std::to_string(count) + " frames, " +
                   std::to_string(parser.stats().checksum_errors) + " checksum errors)";
  }
  return parsed;
}

std::string compare_fields(const FieldValues& expected, const FieldValues& actual) {
  std::string diff;
  if (expected.size() != actual.size()) {
    diff += "field count " + std::to_string(expected.size()) + " vs " +
            std::to_string(actual.size()) + "; ";
  }
  for (size_t i = 0; i < expected.size() && i < actual.size(); ++i) {
    const auto& [name, value] = expected[i];
    if (name != actual[i].first) {
      diff +=
          "field " + std::to_string(i) + " is '" + actual[i].first + "', expected '" + name + "'; ";
    } else if (std::fabs(value - actual[i].second) > 1e-9) {
      diff += name + "=" + format(actual[i].second) + ", expected " + format(value) + "; ";
    }
  }
  return diff;
}

std::string compare_expected_line(const GoldenFrame& frame, const FieldValues& actual) {
  std::string diff;
  for (const auto& [name, text] : frame.expected) {
    double want = 0;
    if (!parse_number(text, &want)) {
      diff += name + ": '" + text + "' is not a number; ";
      continue;
    }
    bool found = false;
    for (const auto& [got_name, got] : actual) {
      if (got_name != name) continue;
      found = true;
      if (std::fabs(got - want) > 1e-9)
        diff += name + "=" + format(got) + ", expected " + text + "; ";
    }
    if (!found) diff += name + ": no such field; ";
  }
  for (const auto& [got_name, got] : actual) {
    bool named = false;
    for (const auto& expected : frame.expected) named = named || expected.first == got_name;
    if (!named) diff += got_name + "=" + format(got) + " is not on the '=' line; ";
  }
  return diff;
}

}  // namespace k40t::test
