#include "k40t_driver/protocol/catalogue.h"

#include <algorithm>
#include <cstdio>
#include <deque>
#include <string>

#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/all.h"

namespace k40t::protocol {
namespace {

std::vector<MessageInfo> build() {
  // Every message struct of every family (messages/all.h).
  std::vector<MessageInfo> all = infos_of(PodMessages{});

  // Every request the host or pod sends gets an ACK entry; where no data-carrying ACK struct was
  // registered, the ACK is the bare response code.
  static std::deque<std::string> ack_names;  // stable storage for the generated names
  std::vector<MessageInfo> acks;
  for (const MessageInfo& m : all) {
    if (kind_of(m.id) != MessageKind::kRequestOrReport || is_periodic_report(m.id)) continue;
    const MessageId ack = ack_id_of(m.id);
    const bool has_own =
        std::any_of(all.begin(), all.end(), [&](const MessageInfo& o) { return o.id == ack; });
    if (has_own) continue;
    MessageInfo info = info_of<PlainAck>();
    info.id = ack;
    ack_names.push_back(std::string(m.name) + "_ack");
    info.name = ack_names.back().c_str();
    info.section = m.section;
    info.direction =
        m.direction == Direction::kHostToPod ? Direction::kPodToHost : Direction::kHostToPod;
    acks.push_back(info);
  }
  all.insert(all.end(), acks.begin(), acks.end());
  std::sort(all.begin(), all.end(),
            [](const MessageInfo& a, const MessageInfo& b) { return a.id < b.id; });
  return all;
}

}  // namespace

const std::vector<MessageInfo>& catalogue() {
  static const std::vector<MessageInfo> all = build();
  return all;
}

const MessageInfo* find_message(MessageId id) {
  const auto& all = catalogue();
  auto it = std::lower_bound(all.begin(), all.end(), id,
                             [](const MessageInfo& m, MessageId v) { return m.id < v; });
  return it != all.end() && it->id == id ? &*it : nullptr;
}

const MessageInfo* find_message(const std::string& name) {
  for (const MessageInfo& m : catalogue()) {
    if (name == m.name) return &m;
  }
  return nullptr;
}

bool is_known_id(MessageId id) {
  return find_message(id) != nullptr;
}

std::string display_name(MessageId id) {
  char hex[16];
  std::snprintf(hex, sizeof(hex), "0x%06X", static_cast<unsigned>(id));
  const MessageInfo* info = find_message(id);
  return info != nullptr ? std::string(info->name) + " (" + hex + ")"
                         : std::string("unknown message ") + hex;
}

}  // namespace k40t::protocol
