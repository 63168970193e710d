// The one reader of the hand-written golden frames, test/data/golden/*.txt (format:
// test/data/golden/README.md). Every reader of those files in the tests goes through here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "field_recorder.h"
#include "k40t_driver/protocol/field_assign.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::testing {

struct GoldenFrame {
  std::string file;     // "camera.txt"
  int line = 0;         // of the frame's first hex line
  std::string section;  // from the title comment "# 3.2.4.3 take_photo: ...", "" if none
  std::string name;     // catalogue name from the title comment, "" if none
  std::vector<uint8_t> bytes;
  FieldValues expected;  // the '=' line, in its order

  // For failure messages; a frame whose lookup failed (already reported) has no file.
  std::string where() const {
    return file.empty() ? "(no golden frame)" : file + ":" + std::to_string(line);
  }
  protocol::FieldArgs args() const { return {expected.begin(), expected.end()}; }
};

// Fails on any malformed line, naming `file` and the line.
Result<std::vector<GoldenFrame>> parse_golden_text(const std::string& text,
                                                   const std::string& file);
Result<std::vector<GoldenFrame>> read_golden_file(const std::string& path);

// K40T_TEST_DATA_DIR/golden/<file>, and every *.txt there, sorted by name.
std::string golden_path(const std::string& file);
std::vector<std::string> golden_file_paths();

}  // namespace k40t::testing
