// The PSDK command catalogue: every command of protocol document chapter 3 and its ACK, with
// name, section, sender, sizes and a type-erased decoder, so tools can decode any PSDK frame
// without knowing its type at compile time.
#pragma once

#include <string>
#include <vector>

#include "k40t_driver/codec/field_visit.h"
#include "k40t_driver/psdk/command.h"

namespace k40t::psdk {

struct CommandInfo {
  CommandKey key;
  PacketType packet = PacketType::kCommand;
  std::string name;
  const char* section = "";
  Sender sender = Sender::kAdapter;
  size_t min_size = 0;  // DATA bytes, the ACK's return code included
  size_t max_size = 0;
  bool acked = false;      // commands: the document gives this command an ACK
  bool encrypted = false;  // the payload sends it AES-encrypted when a key is configured
  // Decodes plain DATA and reports its fields to `sink`; fails with a readable message.
  Status (*describe)(const uint8_t* data, size_t size, codec::FieldSink& sink) = nullptr;
  // Decodes plain DATA and encodes the result again (the golden frames check that the encoder
  // gives back the bytes written by hand).
  Result<Data> (*reencode)(const uint8_t* data, size_t size) = nullptr;
};

// docs/psdk.md#frames: what the payload encrypts (transparent data 0x02/0x02, floating-window text
// 0x02/0x03, everything of set 0x06 and get-position 0x07/0x01).
bool payload_encrypts(CommandKey key);

// Every command and ACK, sorted by set, id, then command before ACK.
const std::vector<CommandInfo>& catalogue();
const CommandInfo* find_command(CommandKey key, PacketType packet);
const CommandInfo* find_command(const std::string& name);

// A whole received frame for tools: its header (command name, set, id, packet type, sequence,
// ACK request, encryption) and then the command's fields; DATA is decrypted with `cipher` when
// the frame is encrypted. Fails, naming the problem, for an unknown command or DATA that does not
// decode (the header fields have been reported by then).
Status describe_frame(const FrameView& frame, const Aes128Ecb* cipher, codec::FieldSink& sink);

template <class T>
Status describe_data(const uint8_t* data, size_t size, codec::FieldSink& sink) {
  Result<T> decoded = decode_data<T>(data, size);
  if (!decoded) return decoded.status();
  describe(decoded.value(), sink);
  return Status::ok();
}

template <class T>
Result<Data> reencode_data(const uint8_t* data, size_t size) {
  Result<T> decoded = decode_data<T>(data, size);
  if (!decoded) return decoded.status();
  return encode_data(decoded.value());
}

}  // namespace k40t::psdk
