// Reader for test/data/golden/*.txt (format: test/data/golden/README.md) and the comparison of
// decoded fields with their expected text.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "k40t_driver/protocol/field_assign.h"
#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::test {

struct GoldenFrame {
  std::string where;  // "file.txt:12" (the frame's first hex line)
  std::vector<uint8_t> bytes;
  protocol::FieldArgs expected;
};

// Fails on any malformed line, naming the file and line.
Result<std::vector<GoldenFrame>> parse_golden_text(const std::string& text,
                                                   const std::string& name);
Result<std::vector<GoldenFrame>> read_golden_file(const std::string& path);

// Collects a decoded message's fields and checks them against expected text values.
class DecodedFields : public protocol::FieldSink {
 public:
  void integer(const char* name, int64_t value) override;
  void unsigned_integer(const char* name, uint64_t value) override;
  void real(const char* name, double value) override;
  void boolean(const char* name, bool value) override;
  void text(const char* name, const std::string& value) override;
  void enumeration(const char* name, int64_t code, const char* label) override;
  void bytes(const char* name, const uint8_t* data, size_t size) override;

  // Ok, or a message naming the field, the expected and the decoded value.
  Status matches(const std::string& name, const std::string& expected) const;

 private:
  enum class Kind { kSigned, kUnsigned, kReal, kBool, kText, kEnum, kBytes };
  struct Value {
    Kind kind = Kind::kSigned;
    int64_t i = 0;
    uint64_t u = 0;
    double d = 0;
    std::string text;  // text, enum label, or the bytes
  };
  std::map<std::string, Value> fields_;
  std::vector<std::string> order_;
  void add(const char* name, Value v);
};

}  // namespace k40t::test
