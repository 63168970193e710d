// Reader for the hand-written golden frame files under test/data/golden/ (format shared by every
// message family):
//
//   # <section> <name>: what the bytes mean, field by field      (comment lines)
//   FD 02 04 01 00 01 01 06 01 00 05 00 xx xx                    (hex, may span lines)
//   = field_name=value field_name=value                           (expected decoded fields)
//
// plus helpers that turn a message's fields() into comparable values.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/protocol/frame.h"

namespace k40t::test {

struct GoldenFrame {
  std::string file;
  int line = 0;                // line of the first hex line, for failure messages
  std::string comment;         // the comment lines just above the frame
  std::vector<uint8_t> bytes;  // the whole frame, STX to checksum
  std::vector<std::pair<std::string, std::string>> expected;  // from the "=" line, in order
  std::string where() const { return file + ":" + std::to_string(line); }
};

// Loads test/data/golden/<name>. Malformed lines make the load fail with a message.
struct GoldenFile {
  std::vector<GoldenFrame> frames;
  std::string error;  // empty when the file parsed
};
GoldenFile load_golden_file(const std::string& name);

// The frame split by the protocol's own parser (header_excluded coverage, NOTES A1).
struct ParsedFrame {
  bool ok = false;
  std::string error;
  protocol::FrameHeader header;
  std::vector<uint8_t> payload;
};
ParsedFrame parse_golden_frame(const GoldenFrame& frame);

// A message's fields as name -> value (integers, reals, bools 0/1, enum codes), in visit order.
using FieldValues = std::vector<std::pair<std::string, double>>;
class FieldCollector : public protocol::FieldSink {
 public:
  void integer(const char* name, int64_t value) override { add(name, static_cast<double>(value)); }
  void unsigned_integer(const char* name, uint64_t value) override {
    add(name, static_cast<double>(value));
  }
  void real(const char* name, double value) override { add(name, value); }
  void boolean(const char* name, bool value) override { add(name, value ? 1 : 0); }
  void text(const char* name, const std::string&) override { unsupported(name); }
  void enumeration(const char* name, int64_t code, const char*) override {
    add(name, static_cast<double>(code));
  }
  void bytes(const char* name, const uint8_t*, size_t) override { unsupported(name); }

  const FieldValues& values() const { return values_; }
  const std::vector<std::string>& unsupported_fields() const { return unsupported_; }

 private:
  void add(const char* name, double value) { values_.emplace_back(name, value); }
  void unsupported(const char* name) { unsupported_.emplace_back(name); }
  FieldValues values_;
  std::vector<std::string> unsupported_;
};

template <class T>
FieldValues field_values(const T& message) {
  FieldCollector collector;
  protocol::visit_fields(message, collector);
  return collector.values();
}

// Differences between two field lists (names and values, reals to 1e-9), "" when equal.
std::string compare_fields(const FieldValues& expected, const FieldValues& actual);
// The "=" line against decoded fields: every field named on the line must match, and every
// decoded field must be named.
std::string compare_expected_line(const GoldenFrame& frame, const FieldValues& actual);

}  // namespace k40t::test
