// Shorthands for the command structs whose shape repeats (command.h describes the contract).
// They expand to exactly the structs that would otherwise be written out by hand; the id, name
// and section of each stand on the line that uses the shorthand, and a comment above a
// K40T_PSDK_SETTING or K40T_PSDK_GET line names the structs it declares, so that grep finds them.
#pragma once

#include "k40t_driver/psdk/command.h"

namespace k40t::psdk {

// A setting whose DATA is one enum byte, `mode`.
template <class Mode, Mode kDefault>
struct ModeValue {
  K40T_PSDK_FIELDS((Mode, mode, wire::u8, kDefault));
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

// A value the adapter reads: the two structs
//   <Camel>Ack  (id, "get_<snake>_ack", section; data = Value) and
//   Get<Camel>  (id, "get_<snake>", section; no data; answered by <Camel>Ack).
#define K40T_PSDK_GET(Camel, snake, Value, set, id, section)                \
  struct Camel##Ack : Reply<CommandSet::set, id, Sender::kPayload>, Value { \
    K40T_PSDK_NAMED("get_" #snake "_ack", section);                         \
  };                                                                        \
  K40T_PSDK_NO_DATA(Get##Camel, set, id, Camel##Ack, "get_" #snake, section)

// A setting the adapter writes and reads back: the three structs
//   Set<Camel>  (set_id, "set_<snake>", set_section; data = Value; PlainAck),
// and K40T_PSDK_GET's <Camel>Ack and Get<Camel> (get_id, get_section).
// The "set" command and the ACK of the "get" share the value struct, as the document gives the
// same bytes for both.
#define K40T_PSDK_SETTING(Camel, snake, Value, set, set_id, set_section, get_id, get_section) \
  struct Set##Camel : Command<CommandSet::set, set_id, Sender::kAdapter, PlainAck>, Value {   \
    K40T_PSDK_NAMED("set_" #snake, set_section);                                              \
  };                                                                                          \
  K40T_PSDK_GET(Camel, snake, Value, set, get_id, get_section)

// Transparent data: 1..max opaque bytes from `sender`, not ACKed.
#define K40T_PSDK_TRANSPARENT(Struct, set, id, sender, max, name, section)                  \
  struct Struct : Command<CommandSet::set, id, Sender::sender, NoAck>, OpaqueData<1, max> { \
    K40T_PSDK_NAMED(name, section);                                                         \
  }

// The members a variable-length struct defines in its .cpp instead of layout() (command.h).
#define K40T_PSDK_VARIABLE_LENGTH() \
  Status validate() const;          \
  void encode(ByteWriter& w) const; \
  Status decode(ByteReader& r);     \
  void describe(FieldSink& sink) const

// A byte (or word) of one-bit flags, bit 0 first: the struct with a bool per flag and the layout
// of wire::bit(0), wire::bit(1), ... in the order the flags are named (at most 9).
//   K40T_PSDK_FLAGS(FocusAssistant, for_auto_focus, for_manual_focus);
// declares `bool for_auto_focus = false;` (bit 0) and `bool for_manual_focus = false;` (bit 1).
#define K40T_PSDK_FLAGS(Struct, ...)                                                  \
  struct Struct {                                                                     \
    K40T_PSDK_EACH_FLAG(K40T_PSDK_FLAG_MEMBER, __VA_ARGS__)                           \
    K40T_PSDK_LAYOUT(s, v) { K40T_PSDK_EACH_FLAG(K40T_PSDK_FLAG_FIELD, __VA_ARGS__) } \
  }
#define K40T_PSDK_FLAG_MEMBER(flag, position) bool flag = false;
#define K40T_PSDK_FLAG_FIELD(flag, position) v(#flag, s.flag, wire::bit(position));
// m(flag, position) for each flag, positions counted from 0.
#define K40T_PSDK_EACH_FLAG(m, ...)                                                           \
  K40T_PSDK_PICK_10TH(__VA_ARGS__, K40T_PSDK_FLAGS9, K40T_PSDK_FLAGS8, K40T_PSDK_FLAGS7,      \
                      K40T_PSDK_FLAGS6, K40T_PSDK_FLAGS5, K40T_PSDK_FLAGS4, K40T_PSDK_FLAGS3, \
                      K40T_PSDK_FLAGS2, K40T_PSDK_FLAGS1, )                                   \
  (m, __VA_ARGS__)
#define K40T_PSDK_PICK_10TH(a1, a2, a3, a4, a5, a6, a7, a8, a9, chosen, ...) chosen
#define K40T_PSDK_FLAGS1(m, a) m(a, 0)
#define K40T_PSDK_FLAGS2(m, a, b) K40T_PSDK_FLAGS1(m, a) m(b, 1)
#define K40T_PSDK_FLAGS3(m, a, b, c) K40T_PSDK_FLAGS2(m, a, b) m(c, 2)
#define K40T_PSDK_FLAGS4(m, a, b, c, d) K40T_PSDK_FLAGS3(m, a, b, c) m(d, 3)
#define K40T_PSDK_FLAGS5(m, a, b, c, d, e) K40T_PSDK_FLAGS4(m, a, b, c, d) m(e, 4)
#define K40T_PSDK_FLAGS6(m, a, b, c, d, e, f) K40T_PSDK_FLAGS5(m, a, b, c, d, e) m(f, 5)
#define K40T_PSDK_FLAGS7(m, a, b, c, d, e, f, g) K40T_PSDK_FLAGS6(m, a, b, c, d, e, f) m(g, 6)
#define K40T_PSDK_FLAGS8(m, a, b, c, d, e, f, g, h) K40T_PSDK_FLAGS7(m, a, b, c, d, e, f, g) m(h, 7)
#define K40T_PSDK_FLAGS9(m, a, b, c, d, e, f, g, h, i) \
  K40T_PSDK_FLAGS8(m, a, b, c, d, e, f, g, h) m(i, 8)
