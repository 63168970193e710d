// Shorthands for the command structs whose shape repeats (command.h describes the contract).
// They expand to exactly the structs that would otherwise be written out by hand; the id, name
// and section of each stand on the line that uses the shorthand, and a comment above a
// K40T_PSDK_SETTING line names the three structs it declares, so that grep finds them.
#pragma once

#include "k40t_driver/psdk/command.h"

namespace k40t::psdk {

// A setting whose DATA is one enum byte, `mode`.
template <class Mode, Mode kDefault>
struct ModeValue {
  Mode mode = kDefault;
  template <class S, class V>
  static void layout(S& s, V&& v) {
    v("mode", s.mode, wire::u8);
  }
};

}  // namespace k40t::psdk

// The name and section of a command or ACK struct, inside its body.
#define K40T_PSDK_NAMED(name, section)       \
  static constexpr const char* kName = name; \
  static constexpr const char* kSection = section

// A command from the adapter that carries no data and is answered by AckType (a "get" command,
// or an action such as "stop zoom" answered by PlainAck).
#define K40T_PSDK_NO_DATA(Struct, set, id, AckType, name, section)                  \
  struct Struct : Command<CommandSet::set, id, Sender::kAdapter, AckType>, NoData { \
    K40T_PSDK_NAMED(name, section);                                                 \
  }

// A setting the adapter writes and reads back: the three structs
//   Set<Camel>  (set_id, "set_<snake>", set_section; data = Value; PlainAck),
//   <Camel>Ack  (get_id, "get_<snake>_ack", get_section; data = Value) and
//   Get<Camel>  (get_id, "get_<snake>", get_section; no data; answered by <Camel>Ack).
// The "set" command and the ACK of the "get" share the value struct, as the document gives the
// same bytes for both.
#define K40T_PSDK_SETTING(Camel, snake, Value, set, set_id, set_section, get_id, get_section) \
  struct Set##Camel : Command<CommandSet::set, set_id, Sender::kAdapter, PlainAck>, Value {   \
    K40T_PSDK_NAMED("set_" #snake, set_section);                                              \
  };                                                                                          \
  struct Camel##Ack : Reply<CommandSet::set, get_id, Sender::kPayload>, Value {               \
    K40T_PSDK_NAMED("get_" #snake "_ack", get_section);                                       \
  };                                                                                          \
  K40T_PSDK_NO_DATA(Get##Camel, set, get_id, Camel##Ack, "get_" #snake, get_section)

// Transparent data: 1..max opaque bytes from `sender`, not ACKed.
#define K40T_PSDK_TRANSPARENT(Struct, set, id, sender, max, name, section)                  \
  struct Struct : Command<CommandSet::set, id, Sender::sender, NoAck>, OpaqueData<1, max> { \
    K40T_PSDK_NAMED(name, section);                                                         \
  }
