#include "golden_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace k40t::testing {

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

// `name=value name="quoted value" ...`, kept in order; a name given twice is an error.
Result<FieldValues> parse_expected(const std::string& text) {
  FieldValues values;
  size_t i = 0;
  while (true) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i >= text.size()) break;
    const size_t equals = text.find('=', i);
    const size_t space = text.find_first_of(" \t", i);
    if (equals == std::string::npos || (space != std::string::npos && space < equals) ||
        equals == i) {
      return Result<FieldValues>::fail("expected name=value at '" + text.substr(i) + "'");
    }
    const std::string name = text.substr(i, equals - i);
    std::string value;
    i = equals + 1;
    if (i < text.size() && text[i] == '"') {
      const size_t close = text.find('"', i + 1);
      if (close == std::string::npos)
        return Result<FieldValues>::fail("unterminated quote in '" + name + "'");
      value = text.substr(i + 1, close - i - 1);
      i = close + 1;
    } else {
      const size_t end = text.find_first_of(" \t\r", i);
      value = text.substr(i, end == std::string::npos ? std::string::npos : end - i);
      i = end == std::string::npos ? text.size() : end;
    }
    for (const auto& [given, unused] : values) {
      if (given == name) return Result<FieldValues>::fail("field '" + name + "' given twice");
    }
    values.emplace_back(name, value);
  }
  return values;
}

}  // namespace

Result<std::vector<GoldenFrame>> parse_golden_text(const std::string& text,
                                                   const std::string& file) {
  static const std::regex kTitle(R"(^# (\d+(?:\.\d+)+) (\w+):)");
  std::vector<GoldenFrame> frames;
  GoldenFrame current;
  bool in_frame = false;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  const auto fail = [&](const std::string& why) {
    return Result<std::vector<GoldenFrame>>::fail(file + ":" + std::to_string(number) + ": " + why);
  };
  const auto unfinished = [&] {
    return fail("the frame starting at " + current.where() + " has no '=' line");
  };
  while (std::getline(in, line)) {
    ++number;
    if (is_blank(line)) continue;
    std::smatch title;
    if (std::regex_search(line, title, kTitle)) {
      if (in_frame) return unfinished();
      current.section = title[1];
      current.name = title[2];
      continue;
    }
    if (line[0] == '#') continue;
    if (line[0] == '=') {
      if (!in_frame) return fail("'=' line without the hex lines of a frame before it");
      Result<FieldValues> expected = parse_expected(line.substr(1));
      if (!expected) return fail(expected.error());
      current.expected = std::move(expected.value());
      frames.push_back(std::move(current));
      current = GoldenFrame();
      in_frame = false;
      continue;
    }
    Result<std::vector<uint8_t>> bytes = parse_hex_line(line);
    if (!bytes) return fail(bytes.error());
    if (!in_frame) {
      current.file = file;
      current.line = number;
    }
    in_frame = true;
    current.bytes.insert(current.bytes.end(), bytes->begin(), bytes->end());
  }
  if (in_frame) return unfinished();
  if (frames.empty()) return fail("no frames");
  return frames;
}

Result<std::vector<GoldenFrame>> read_golden_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Result<std::vector<GoldenFrame>>::fail("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  return parse_golden_text(text.str(), std::filesystem::path(path).filename().string());
}

std::string golden_path(const std::string& file) {
  return std::string(K40T_TEST_DATA_DIR) + "/golden/" + file;
}

std::vector<std::string> golden_file_paths() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(golden_path(""))) {
    if (entry.path().extension() == ".txt") paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

}  // namespace k40t::testing
