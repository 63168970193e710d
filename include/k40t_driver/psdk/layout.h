// PSDK command structs describe their DATA with the protocol-neutral declarative layouts of
// codec/layout.h (shared with the pod protocol). Everything in the PSDK is little-endian
// (section 2.1 and 3.3.9), the visitors' default, and every byte of a layout is required.
#pragma once

#include "k40t_driver/codec/field_list.h"
#include "k40t_driver/codec/layout.h"

namespace k40t::psdk {

using codec::ByteReader;
using codec::ByteWriter;
using codec::FieldSink;

namespace wire = codec::wire;
using codec::LayoutReader;
using codec::LayoutSink;
using codec::LayoutSizer;
using codec::LayoutValidator;
using codec::LayoutWriter;

}  // namespace k40t::psdk

// The signature of a struct's layout() in one line (as the pod messages' K40T_LAYOUT); the body
// lists the fields:
//   K40T_PSDK_LAYOUT(s, v) {
//     v("mode", s.mode, wire::u8);
//   }
// `s` is the struct (const when validating, encoding or describing), `v` the visitor.
#define K40T_PSDK_LAYOUT(s, v)  \
  template <class S_, class V_> \
  static void layout([[maybe_unused]] S_& s, [[maybe_unused]] V_&& v)

// A command whose DATA is its fields in order, each declared once (codec/field_list.h):
//   K40T_PSDK_FIELDS((uint8_t, percentage, wire::u8));
#define K40T_PSDK_FIELDS(...) K40T_FIELD_LIST(K40T_PSDK_LAYOUT, __VA_ARGS__)
