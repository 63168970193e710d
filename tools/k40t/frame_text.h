// How k40t shows a frame: one JSON object (decode), one human line (monitor, send), and the
// end-of-run counters (stderr).
#pragma once

#include <cstdint>
#include <string>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/session/dispatcher.h"

namespace k40t::tool {

// "request", "report", "ack", "status" or "other" (section 2.1's high byte, reports 0x01..0x0F).
const char* kind_name(protocol::MessageId id);
// "0x04/0x01"
std::string address_text(protocol::Address address);
// "0x000400"
std::string id_text(protocol::MessageId id);

// {"offset":..,"id":..,"name":..,"section":..,"kind":..,"direction":..,"src":..,"dst":..,"seq":..,
//  "crc_coverage":..,"payload":"01 00","fields":{...}} or "error" instead of "fields".
// `*decoded` (if given) tells whether the payload decoded.
std::string frame_json(const protocol::FrameView& frame, uint64_t offset,
                       const protocol::CodecOptions& codec, bool* decoded = nullptr);

// A message's fields as text, one add(name, value) per field: numbers in decimal (reals with
// `real_format`, e.g. "%g"), booleans as 1/0. Text, enums and bytes are each view's own.
class FieldTextSink : public protocol::FieldSink {
 public:
  explicit FieldTextSink(const char* real_format) : real_format_(real_format) {}
  void integer(const char* name, int64_t value) override { add(name, std::to_string(value)); }
  void unsigned_integer(const char* name, uint64_t value) override {
    add(name, std::to_string(value));
  }
  void real(const char* name, double value) override;
  void boolean(const char* name, bool value) override { add(name, value ? "1" : "0"); }

 protected:
  virtual void add(const std::string& name, const std::string& value) = 0;

 private:
  const char* real_format_;
};

// "name field=value field=value" with the message's fields, or "name: <decode error>"; long
// lines are cut at `max_chars` with "...".
std::string frame_summary(const protocol::FrameView& frame, const protocol::CodecOptions& codec,
                          bool* decoded = nullptr, size_t max_chars = 240);
// The payload of message `id` as "field=value ...", or why it does not decode.
std::string payload_summary(protocol::MessageId id, const uint8_t* payload, size_t size,
                            const protocol::CodecOptions& codec, bool* decoded = nullptr);

// "good frames 12, checksum errors 1, ..." on one line; `undecodable` counts the known frames
// whose payload did not decode.
std::string counters_text(const session::DispatcherStats& stats, uint64_t undecodable);

}  // namespace k40t::tool
