// The message catalogue: every message id of NOTES.md with its name, section, direction and a
// type-erased decoder, so tools can decode any frame without knowing its type at compile time.
#pragma once

#include <string>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/protocol/message.h"

namespace k40t::protocol {

struct MessageInfo {
  MessageId id = 0;
  const char* name = "";
  const char* section = "";
  Direction direction = Direction::kPodToHost;
  size_t min_size = 0;
  size_t size = 0;
  // Decodes the payload and reports its fields to `sink`; fails with a readable message.
  Status (*describe)(const uint8_t* payload, size_t size, const CodecOptions& options,
                     FieldSink& sink) = nullptr;
};

template <class T>
Status describe_payload(const uint8_t* payload, size_t size, const CodecOptions& options,
                        FieldSink& sink) {
  Result<T> decoded = decode_payload<T>(payload, size, options);
  if (!decoded) return decoded.status();
  visit_fields(decoded.value(), sink);
  return Status::ok();
}

template <class T>
MessageInfo info_of() {
  return MessageInfo{T::kId, T::kName, T::kSection, T::kDirection, T::kMinSize, T::kSize,
                     &describe_payload<T>};
}

// Every message, sorted by id. ACKs of requests whose ACK carries only the response code are
// listed too (as "<request name>_ack" with the PlainAck layout).
const std::vector<MessageInfo>& catalogue();
const MessageInfo* find_message(MessageId id);
const MessageInfo* find_message(const std::string& name);
bool is_known_id(MessageId id);

// Each message family adds its own entries (src/protocol/messages/<family>.cpp).
void add_gimbal_messages(std::vector<MessageInfo>& out);
void add_thermal_messages(std::vector<MessageInfo>& out);
void add_visible_messages(std::vector<MessageInfo>& out);
void add_camera_messages(std::vector<MessageInfo>& out);
void add_laser_messages(std::vector<MessageInfo>& out);
void add_sbus_messages(std::vector<MessageInfo>& out);

}  // namespace k40t::protocol
