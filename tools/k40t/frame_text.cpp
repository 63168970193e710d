#include "frame_text.h"

#include <cstdio>

#include "input.h"
#include "json_sink.h"
#include "k40t_driver/codec/enum_names.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/field_assign.h"

namespace k40t::tool {

const char* kind_name(protocol::MessageId id) {
  using protocol::MessageKind;
  const MessageKind kind = protocol::kind_of(id);
  if (kind == MessageKind::kRequestOrReport) {
    return protocol::is_periodic_report(id) ? "report" : "request";
  }
  static constexpr EnumName<MessageKind> kNames[] = {{MessageKind::kAck, "ack"},
                                                     {MessageKind::kStatus, "status"}};
  return name_in(kNames, kind, "other");
}

std::string address_text(protocol::Address address) {
  char buffer[16];
  std::snprintf(buffer, sizeof(buffer), "0x%02X/0x%02X", address.system, address.component);
  return buffer;
}

std::string id_text(protocol::MessageId id) {
  char buffer[16];
  std::snprintf(buffer, sizeof(buffer), "0x%06X", static_cast<unsigned>(id));
  return buffer;
}

std::string frame_json(const protocol::FrameView& frame, uint64_t offset,
                       const protocol::CodecOptions& codec, bool* decoded_out) {
  const protocol::MessageInfo* info = protocol::find_message(frame.header.message_id);
  JsonWriter out;
  out.begin_object();
  out.key("offset");
  out.unsigned_integer(offset);
  out.member("id", id_text(frame.header.message_id));
  const auto member_or_null = [&](const char* key, const char* value) {
    out.key(key);
    if (value != nullptr) {
      out.string(value);
    } else {
      out.null();
    }
  };
  member_or_null("name", info ? info->name : nullptr);
  member_or_null("section", info ? info->section : nullptr);
  out.member("kind", kind_name(frame.header.message_id));
  member_or_null("direction", info ? protocol::to_string(info->direction) : nullptr);
  out.member("src", address_text(frame.header.source));
  out.member("dst", address_text(frame.header.destination));
  out.key("seq");
  out.unsigned_integer(frame.header.sequence);
  out.member("crc_coverage", protocol::to_string(frame.coverage));
  out.member("payload", to_hex(frame.payload, frame.payload_size));
  if (decoded_out != nullptr) *decoded_out = false;
  if (info == nullptr) {
    out.member("error", "unknown message id " + id_text(frame.header.message_id));
  } else {
    JsonWriter fields;
    fields.begin_object();
    JsonFieldSink sink(fields);
    const Status decoded = info->describe(frame.payload, frame.payload_size, codec, sink);
    fields.end_object();
    if (decoded_out != nullptr) *decoded_out = decoded.is_ok();
    if (decoded) {
      out.key("fields");
      // The nested object is complete JSON: splice it in as the member's value.
      out.raw(fields.text());
    } else {
      out.member("error", decoded.message());
    }
  }
  out.end_object();
  return out.text();
}

void FieldTextSink::real(const char* name, double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), real_format_, value);
  add(name, buffer);
}

namespace {

// "name=value" pairs for humans: reals as %g, enums by label, bytes dotted.
class SummarySink : public FieldTextSink {
 public:
  SummarySink() : FieldTextSink("%g") {}
  void text(const char* name, const std::string& value) override { add(name, "\"" + value + "\""); }
  // One token per field: the label as `k40t send` accepts it ("busy_repeated_request(8)").
  void enumeration(const char* name, int64_t code, const char* label) override {
    add(name, label ? protocol::normalize_label(label) + "(" + std::to_string(code) + ")"
                    : std::to_string(code) + "(undefined)");
  }
  void bytes(const char* name, const uint8_t* data, size_t size) override {
    std::string joined;
    for (size_t i = 0; i < size; ++i) joined += (i ? "." : "") + std::to_string(data[i]);
    add(name, joined);
  }
  const std::string& line() const { return line_; }

 private:
  void add(const std::string& name, const std::string& value) override {
    if (!line_.empty()) line_ += ' ';
    line_ += name;
    line_ += '=';
    line_ += value;
  }
  std::string line_;
};

}  // namespace

std::string payload_summary(protocol::MessageId id, const uint8_t* payload, size_t size,
                            const protocol::CodecOptions& codec, bool* decoded_out) {
  if (decoded_out != nullptr) *decoded_out = false;
  const protocol::MessageInfo* info = protocol::find_message(id);
  if (info == nullptr) return "payload " + to_hex(payload, size);
  SummarySink sink;
  const Status decoded = info->describe(payload, size, codec, sink);
  if (decoded_out != nullptr) *decoded_out = decoded.is_ok();
  if (!decoded)
    return "undecodable: " + decoded.message() + " (payload " + to_hex(payload, size) + ")";
  return sink.line();
}

std::string frame_summary(const protocol::FrameView& frame, const protocol::CodecOptions& codec,
                          bool* decoded, size_t max_chars) {
  const protocol::MessageInfo* info = protocol::find_message(frame.header.message_id);
  std::string line = info ? info->name : "unknown " + id_text(frame.header.message_id);
  line += " " + address_text(frame.header.source) + ">" + address_text(frame.header.destination) +
          " #" + std::to_string(frame.header.sequence);
  const std::string fields =
      payload_summary(frame.header.message_id, frame.payload, frame.payload_size, codec, decoded);
  if (!fields.empty()) line += " " + fields;
  if (line.size() > max_chars) line = line.substr(0, max_chars - 3) + "...";
  return line;
}

std::string counters_text(const session::DispatcherStats& stats, uint64_t undecodable) {
  const protocol::ParserStats& p = stats.parser;
  std::string text =
      "good frames " + std::to_string(p.frames_good) + ", checksum errors " +
      std::to_string(p.checksum_errors) + ", length errors " + std::to_string(p.length_errors) +
      ", discarded bytes " + std::to_string(p.bytes_discarded) + ", unknown ids " +
      std::to_string(p.unknown_ids) + ", sequence gaps " + std::to_string(p.sequence_gaps) + " (" +
      std::to_string(p.frames_lost) + " frames lost, " + std::to_string(p.frames_repeated) +
      " repeated), decode errors " + std::to_string(stats.decode_errors + undecodable) +
      ", crc coverage " + protocol::to_string(stats.locked_coverage);
  return text;
}

}  // namespace k40t::tool
