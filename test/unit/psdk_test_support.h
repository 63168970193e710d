// Test helpers for the PSDK layer: docs/psdk.md#frames' frame vectors, a frame builder, and a
// FieldSink that records "name=value" lines.
#pragma once

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/psdk/frame.h"

namespace k40t::psdk::testing {

using Bytes = std::vector<uint8_t>;

// docs/psdk.md#frames' whole-frame vectors: get PSDK version (cmd set 0x01, id 0x02, seq 0, ACK
// requested) and its ACK, DATA 0x00 (OK) + version 1.3.0.0 as {debug, modify, minor, major}.
inline const Bytes kGetVersion = {0xaa, 0x10, 0x00, 0x01, 0x00, 0x00, 0x01, 0x02,
                                  0x00, 0x00, 0xf2, 0x68, 0xbc, 0x0f, 0x4c, 0x90};
inline const Bytes kGetVersionAck = {0xaa, 0x15, 0x00, 0x20, 0x00, 0x00, 0x01,
                                     0x02, 0x00, 0x00, 0x0b, 0x9d, 0x00, 0x00,
                                     0x00, 0x03, 0x01, 0xaa, 0x7e, 0x6e, 0xbf};

// A frame built by the encoder under test (for streams and sessions, never as a golden vector).
inline Bytes make_frame(const FrameHeader& header, const Bytes& data,
                        const Aes128Ecb* cipher = nullptr) {
  auto f = encode_frame(header, data.data(), data.size(), cipher);
  EXPECT_TRUE(f) << f.error();
  return f ? Bytes(f->data(), f->data() + f->size()) : Bytes{};
}

// A command frame (encoded by the code under test) of `key` with `sequence` and DATA `data`.
inline Bytes command_frame(CommandKey key, uint16_t sequence, const Bytes& data,
                           AckRequest ack = AckRequest::kAfterExecution,
                           const Aes128Ecb* cipher = nullptr) {
  FrameHeader h;
  h.command = key;
  h.sequence = sequence;
  h.ack_request = ack;
  h.encryption = cipher ? Encryption::kAes : Encryption::kNone;
  return make_frame(h, data, cipher);
}

class RecordingSink : public protocol::FieldSink {
 public:
  std::vector<std::string> lines;

  void integer(const char* name, int64_t value) override { add(name, std::to_string(value)); }
  void unsigned_integer(const char* name, uint64_t value) override {
    add(name, std::to_string(value));
  }
  void real(const char* name, double value) override {
    std::ostringstream out;
    out << std::setprecision(17) << value;
    add(name, out.str());
  }
  void boolean(const char* name, bool value) override { add(name, value ? "true" : "false"); }
  void text(const char* name, const std::string& value) override { add(name, "\"" + value + "\""); }
  void enumeration(const char* name, int64_t code, const char* label) override {
    add(name, std::to_string(code) + "(" + (label ? label : "?") + ")");
  }
  void bytes(const char* name, const uint8_t* data, size_t size) override {
    std::ostringstream out;
    for (size_t i = 0; i < size; ++i)
      out << std::hex << std::setw(2) << std::setfill('0') << int(data[i]);
    add(name, out.str());
  }
  bool has(const std::string& line) const {
    for (const auto& l : lines) {
      if (l == line) return true;
    }
    return false;
  }

 private:
  void add(const char* name, const std::string& value) {
    lines.push_back(std::string(name) + "=" + value);
  }
};

}  // namespace k40t::psdk::testing
