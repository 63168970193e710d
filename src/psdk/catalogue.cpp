#include "k40t_driver/psdk/catalogue.h"

#include <algorithm>
#include <cstdio>

#include "k40t_driver/psdk/commands/all.h"

namespace k40t::psdk {
namespace {

template <class T>
CommandInfo info_of(CommandKey key, const std::string& name, const char* section) {
  CommandInfo info;
  info.key = key;
  info.packet = T::kPacket;
  info.name = name;
  info.section = section;
  info.min_size = min_data_size<T>();
  info.max_size = max_data_size<T>();
  info.encrypted = payload_encrypts(key);
  info.describe = &describe_data<T>;
  info.reencode = &reencode_data<T>;
  return info;
}

// Adds the command and, unless the document says it is not ACKed, its ACK.
template <class Cmd>
void add(std::vector<CommandInfo>& out) {
  using Ack = typename Cmd::Ack;
  CommandInfo command = info_of<Cmd>(Cmd::key(), Cmd::kName, Cmd::kSection);
  command.sender = Cmd::kSender;
  command.acked = !std::is_same_v<Ack, NoAck>;
  out.push_back(command);
  if constexpr (std::is_same_v<Ack, PlainAck>) {
    CommandInfo ack =
        info_of<PlainAck>(Cmd::key(), std::string(Cmd::kName) + "_ack", Cmd::kSection);
    ack.sender = other_side(Cmd::kSender);
    out.push_back(ack);
  } else if constexpr (!std::is_same_v<Ack, NoAck>) {
    static_assert(Ack::kSet == Cmd::kSet && Ack::kId == Cmd::kId, "ACK struct of another command");
    static_assert(Ack::kSender != Cmd::kSender, "an ACK comes from the other side");
    CommandInfo ack = info_of<Ack>(Ack::key(), Ack::kName, Ack::kSection);
    ack.sender = Ack::kSender;
    out.push_back(ack);
  }
}

template <class... Cmds>
void add_all(std::vector<CommandInfo>& out, TypeList<Cmds...>) {
  (add<Cmds>(out), ...);
}

std::vector<CommandInfo> build() {
  std::vector<CommandInfo> all;
  add_all(all, AllCommands{});
  std::sort(all.begin(), all.end(), [](const CommandInfo& a, const CommandInfo& b) {
    if (a.key != b.key) return a.key < b.key;
    return a.packet < b.packet;
  });
  return all;
}

}  // namespace

bool payload_encrypts(CommandKey key) {
  return key == key_of(CommandSet::kAppFunction, 0x02) ||
         key == key_of(CommandSet::kAppFunction, 0x03) ||
         key.set == static_cast<uint8_t>(CommandSet::kOsdkFunction) ||
         key == key_of(CommandSet::kPositioning, 0x01);
}

Status describe_frame(const FrameView& frame, const Aes128Ecb* cipher, codec::FieldSink& sink) {
  const FrameHeader& h = frame.header;
  const CommandInfo* info = find_command(h.command, h.packet_type);
  sink.text("command", info ? info->name : std::string("unknown"));
  codec::detail::SinkAdapter out{sink};
  out("cmd_set", static_cast<CommandSet>(h.command.set));
  out("cmd_id", h.command.id);
  out("packet_type", h.packet_type);
  out("sequence", h.sequence);
  out("ack_request", h.ack_request);
  out("encryption", h.encryption);
  const Result<Data> data = open_data(frame, cipher);
  if (!data) return data.status();
  if (info == nullptr) {
    sink.bytes("data", data->data(), data->size);
    char text[64];
    std::snprintf(text, sizeof(text), "command 0x%02X/0x%02X%s is not in the document",
                  h.command.set, h.command.id, h.packet_type == PacketType::kAck ? " ACK" : "");
    return Status::fail(text);
  }
  return info->describe(data->data(), data->size, sink);
}

const std::vector<CommandInfo>& catalogue() {
  static const std::vector<CommandInfo> all = build();
  return all;
}

const CommandInfo* find_command(CommandKey key, PacketType packet) {
  for (const CommandInfo& c : catalogue()) {
    if (c.key == key && c.packet == packet) return &c;
  }
  return nullptr;
}

const CommandInfo* find_command(const std::string& name) {
  for (const CommandInfo& c : catalogue()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

}  // namespace k40t::psdk
