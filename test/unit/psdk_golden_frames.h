// Where the hand-written whole PSDK frames are (test/data/psdk_golden/*.txt, format and
// conventions in the README there), and which (set, id, packet type) they cover, read from each
// frame's own header bytes. Header-only and gtest-free: the frame checks
// (test_psdk_golden_frames.cpp) and the coverage test of the bridge's dispatch table
// (test/ros/unit/test_skyport_golden_coverage.cpp, another binary) both use it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace k40t::psdk::test {

inline std::string psdk_golden_dir() {
  return std::string(K40T_TEST_DATA_DIR) + "/psdk_golden";
}

inline std::vector<std::string> psdk_golden_paths() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(psdk_golden_dir())) {
    if (entry.path().extension() == ".txt") paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

// (set, id, packet type: 0 command, 1 ACK).
using GoldenKey = std::tuple<uint8_t, uint8_t, uint8_t>;

// Every frame's key: the first hex line of each frame holds its header (bytes 3, 6, 7).
inline std::set<GoldenKey> psdk_golden_keys() {
  std::set<GoldenKey> keys;
  for (const std::string& path : psdk_golden_paths()) {
    std::ifstream in(path);
    std::string line;
    bool in_frame = false;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      if (line[0] == '=') {
        in_frame = false;
        continue;
      }
      if (in_frame) continue;
      in_frame = true;
      std::istringstream hex(line);
      std::vector<unsigned> bytes;
      unsigned byte = 0;
      while (bytes.size() < 8 && hex >> std::hex >> byte) bytes.push_back(byte);
      if (bytes.size() == 8) {
        keys.emplace(static_cast<uint8_t>(bytes[6]), static_cast<uint8_t>(bytes[7]),
                     static_cast<uint8_t>(bytes[3] >> 5 & 1u));
      }
    }
  }
  return keys;
}

}  // namespace k40t::psdk::test
