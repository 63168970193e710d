// Entry-level reader (titles, sections, names) of the hand-written golden frame files test/data/golden/*.txt. Each entry is
//   # <section> <name>: what the bytes mean, field by field
//   # (more comment lines)
//   FD 07 01 01 ...            (hex; may continue on following lines)
//   = field=value field=value  (expected decoded fields, names as in fields(); enums and
//                               booleans as numbers; a bare "=" for a message without fields)
// A '#' line that does not start "# <section> <name>:" (digits and dots, then a snake_case name)
// is a comment, e.g. a file header. The checksum bytes were computed with test/data/frame_crc.py,
// independently of the C++ code.
#pragma once

#include <cctype>
#include <cstdint>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace k40t::testing {

struct GoldenFrame {
  std::string file;
  int line = 0;  // of the '#' line
  std::string section;
  std::string name;
  std::string comment;
  std::vector<uint8_t> bytes;
  std::vector<std::pair<std::string, std::string>> expected;  // field name, value text

  std::string where() const { return file + ":" + std::to_string(line) + " (" + name + ")"; }
};

// Parses one file; on a malformed line returns what it read so far and sets *error.
inline std::vector<GoldenFrame> load_golden_file(const std::string& path, std::string* error) {
  std::vector<GoldenFrame> frames;
  std::ifstream in(path);
  if (!in) {
    *error = "cannot open " + path;
    return frames;
  }
  std::string line;
  int number = 0;
  bool open = false;  // an entry whose '=' line has not been seen yet
  const std::regex title(R"(^# (\d+(?:\.\d+)+) (\w+):)");
  auto fail = [&](const std::string& why) {
    *error = path + ":" + std::to_string(number) + ": " + why;
    return frames;
  };
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    std::smatch m;
    if (std::regex_search(line, m, title)) {
      if (open) return fail("entry without '=' line before this one");
      GoldenFrame f;
      f.file = path;
      f.line = number;
      f.section = m[1];
      f.name = m[2];
      f.comment = line.substr(m.length(0));
      frames.push_back(f);
      open = true;
    } else if (line[0] == '#') {
      if (open && frames.back().bytes.empty()) frames.back().comment += "\n" + line.substr(1);
    } else if (line[0] == '=') {
      if (!open) return fail("'=' line without a '#' line");
      std::istringstream words(line.substr(1));
      std::string token;
      while (words >> token) {
        const size_t eq = token.find('=');
        if (eq == std::string::npos || eq == 0) return fail("expected field=value, got " + token);
        frames.back().expected.emplace_back(token.substr(0, eq), token.substr(eq + 1));
      }
      open = false;
    } else {
      if (!open) return fail("hex bytes outside an entry");
      std::istringstream words(line);
      std::string hex;
      while (words >> hex) {
        if (hex.size() != 2 || !std::isxdigit(static_cast<unsigned char>(hex[0])) ||
            !std::isxdigit(static_cast<unsigned char>(hex[1]))) {
          return fail("expected a hex byte, got " + hex);
        }
        frames.back().bytes.push_back(static_cast<uint8_t>(std::stoul(hex, nullptr, 16)));
      }
    }
  }
  if (open) return fail("last entry has no '=' line");
  return frames;
}

// The `index`-th entry (0-based) called `name`, or nullptr.
inline const GoldenFrame* find_golden(const std::vector<GoldenFrame>& frames,
                                      const std::string& name, size_t index = 0) {
  for (const GoldenFrame& f : frames) {
    if (f.name == name && index-- == 0) return &f;
  }
  return nullptr;
}

}  // namespace k40t::testing
