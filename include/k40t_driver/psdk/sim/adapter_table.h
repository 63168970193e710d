// skyport_sim's own table of the payload's ACKs and its own writer of the commands it sends,
// written from the PSDK protocol document with byte offsets (section per entry; the document's
// byte N of an ACK is offset N-1 of DATA, the return code at offset 0), little-endian (2.1). It
// does not use psdk/commands' structs, which the payload encodes with: a layout both sides got
// wrong the same way would pass every check otherwise. The layouts where DJI's headers disagree
// with the document (gimbal state, SD card, photo mode: docs/psdk.md P28..P30) are read by
// payload_reading.h, also from the sources directly.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/psdk/frame.h"

namespace k40t::psdk::sim::table {

enum class Kind : uint8_t { kU8, kU16, kI16, kU32, kF32, kBit, kText };

struct Field {
  const char* name;
  uint8_t offset;  // in the ACK's DATA, the return code at 0
  Kind kind;
  uint8_t extra = 0;   // kBit: the bit (0 = LSB); kText: the field's size in bytes
  double scale = 1.0;  // the value read is the raw number times this (0.1 mm, 0.1 deg/s...)
};

struct AckEntry {
  uint8_t set, id;
  const char* name;     // the command's, for the check report
  const char* section;  // of the document
  uint8_t size;         // DATA bytes, the return code included
  std::vector<Field> fields;
};

// Every ACK the simulator reads with the table.
const std::vector<AckEntry>& acks();
// The entry of (set, id); nullptr when the table has none.
const AckEntry* find_ack(CommandKey key);

// An ACK read with its entry: every field by name (bits as 0/1, texts up to their NUL).
struct Reading {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> texts;
  double number(const std::string& name) const;  // 0 when the entry has no such field
  std::string text(const std::string& name) const;
};

// Fails, naming the command, for a key without entry, an empty ACK, a return code other than
// 0x00, or fewer bytes than the entry's size.
Result<Reading> read(CommandKey key, const Data& ack);

// DATA of a command, written field by field in the document's order.
class Request {
 public:
  Request& u8(uint8_t value);
  Request& u16(uint16_t value);
  Request& i16(int16_t value);
  Request& u32(uint32_t value);
  Request& f32(float value);
  Request& f64(double value);
  Request& text(const std::string& value);  // the bytes as they are, no NUL
  const std::vector<uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<uint8_t> bytes_;
};

}  // namespace k40t::psdk::sim::table
