// The message catalogue: every message id of the document (docs/protocol/) with its name, section,
// direction and a type-erased decoder, so tools can decode any frame without knowing its type at
// compile time.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/field_assign.h"
#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_list.h"

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
  // Builds and validates a payload from `name=value` text arguments (field_assign.h lists the
  // spellings); unknown names fail with the list of the message's fields.
  Result<Payload> (*encode_args)(const std::map<std::string, std::string>& args,
                                 const CodecOptions& options) = nullptr;
  // Reports a default-constructed message's fields (names, kinds, defaults): CLI help.
  void (*default_fields)(FieldSink& sink) = nullptr;
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
void describe_defaults(FieldSink& sink) {
  visit_fields(T{}, sink);
}

template <class T>
MessageInfo info_of() {
  return MessageInfo{T::kId,
                     T::kName,
                     T::kSection,
                     T::kDirection,
                     T::kMinSize,
                     T::kSize,
                     &describe_payload<T>,
                     &encode_args<T>,
                     &describe_defaults<T>};
}

// Every message, sorted by id. ACKs of requests whose ACK carries only the response code are
// listed too (as "<request name>_ack" with the PlainAck layout).
const std::vector<MessageInfo>& catalogue();
const MessageInfo* find_message(MessageId id);
const MessageInfo* find_message(const std::string& name);
bool is_known_id(MessageId id);
// "laser_range (0x000400)", or "unknown message 0x123456": for error messages and logs.
std::string display_name(MessageId id);

// The entries of a list of message structs (message_list.h), in list order.
template <class... T>
std::vector<MessageInfo> infos_of(MessageList<T...>) {
  return {info_of<T>()...};
}

}  // namespace k40t::protocol
