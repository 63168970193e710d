#include "camera_golden.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

namespace k40t::protocol::testing {

std::vector<GoldenFrame> load_golden(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  const std::regex title(R"(^# (\d+(?:\.\d+)+) (\w+):)");
  std::vector<GoldenFrame> frames;
  GoldenFrame current;
  bool open = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::smatch m;
    if (std::regex_search(line, m, title)) {
      EXPECT_FALSE(open) << path << ":" << current.line << ": entry has no '=' line";
      current = GoldenFrame{number, m[1], m[2], {}, {}};
      open = true;
    } else if (!line.empty() && line[0] == '=') {
      EXPECT_TRUE(open) << path << ":" << number << ": '=' line without an entry";
      std::istringstream fields(line.substr(1));
      for (std::string pair; fields >> pair;) {
        const size_t eq = pair.find('=');
        EXPECT_NE(eq, std::string::npos) << path << ":" << number << ": '" << pair << "'";
        if (eq != std::string::npos)
          current.expected.emplace_back(pair.substr(0, eq), pair.substr(eq + 1));
      }
      frames.push_back(current);
      open = false;
    } else if (open && !line.empty() && line[0] != '#') {
      std::istringstream hex(line);
      for (std::string byte; hex >> byte;) {
        char* end = nullptr;
        const unsigned long value = std::strtoul(byte.c_str(), &end, 16);
        EXPECT_TRUE(byte.size() == 2 && *end == '\0' && value <= 0xFF)
            << path << ":" << number << ": '" << byte << "' is not a hex byte";
        current.bytes.push_back(static_cast<uint8_t>(value));
      }
    }
  }
  EXPECT_FALSE(open) << path << ": last entry has no '=' line";
  return frames;
}

std::vector<GoldenFrame> load_camera_golden() {
  return load_golden(std::string(K40T_TEST_DATA_DIR) + "/golden/camera.txt");
}

const GoldenFrame* find_golden(const std::vector<GoldenFrame>& all, const std::string& name) {
  for (const GoldenFrame& frame : all) {
    if (frame.name == name) return &frame;
  }
  return nullptr;
}

void RecordedFields::integer(const char* name, int64_t value) {
  values_.emplace_back(name, std::to_string(value));
}
void RecordedFields::unsigned_integer(const char* name, uint64_t value) {
  values_.emplace_back(name, std::to_string(value));
}
void RecordedFields::real(const char* name, double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  values_.emplace_back(name, out.str());
  reals_[name] = value;
}
void RecordedFields::boolean(const char* name, bool value) {
  values_.emplace_back(name, value ? "1" : "0");
}
void RecordedFields::text(const char* name, const std::string& value) {
  values_.emplace_back(name, value);
}
void RecordedFields::enumeration(const char* name, int64_t code, const char*) {
  values_.emplace_back(name, std::to_string(code));
}
void RecordedFields::bytes(const char* name, const uint8_t* data, size_t size) {
  std::string hex;
  char buffer[3];
  for (size_t i = 0; i < size; ++i) {
    std::snprintf(buffer, sizeof(buffer), "%02X", data[i]);
    hex += buffer;
  }
  values_.emplace_back(name, hex);
}

::testing::AssertionResult fields_match(const RecordedFields& actual, const FieldValues& expected) {
  std::ostringstream problems;
  const FieldValues& got = actual.values_;
  if (got.size() != expected.size()) {
    problems << " expected " << expected.size() << " fields, got " << got.size() << ";";
  }
  for (size_t i = 0; i < std::min(got.size(), expected.size()); ++i) {
    const auto& [name, value] = got[i];
    const auto& [want_name, want] = expected[i];
    if (name != want_name) {
      problems << " field " << i << " is '" << name << "', expected '" << want_name << "';";
      continue;
    }
    const auto real = actual.reals_.find(name);
    if (real != actual.reals_.end()) {
      char* end = nullptr;
      const double want_value = std::strtod(want.c_str(), &end);
      const double tolerance = 1e-9 * std::max(1.0, std::fabs(want_value));
      if (*end != '\0' || std::fabs(real->second - want_value) > tolerance) {
        problems << " " << name << "=" << value << ", expected " << want << ";";
      }
    } else if (value != want) {
      problems << " " << name << "=" << value << ", expected " << want << ";";
    }
  }
  if (problems.str().empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << problems.str();
}

namespace detail {

bool FieldAssigner::assign(const std::string& text, double& field) {
  char* end = nullptr;
  field = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0';
}

}  // namespace detail

}  // namespace k40t::protocol::testing
