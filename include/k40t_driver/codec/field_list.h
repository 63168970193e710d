// A message whose wire form is its fields in order declares each field once, as one entry
//   (type, name, wire kind)  or  (type, name, wire kind, initial value)
// that gives both the member and its line in layout(); without an initial value the member is
// value-initialised: 0, false, the enum's 0, or a struct member's own defaults. An entry of two,
//   (reserved, wire::Reserved{n})   or   (start, wire::fixed(0x00, "start setting"))
// is a layout line with no member: a reserved gap or a fixed byte. protocol/message_layout.h and
// psdk/layout.h wrap it for their families:
//   K40T_FIELDS((uint8_t, percentage, wire::u8),
//               (float, q0, wire::f32, 1.0f));
// expands to
//   uint8_t percentage{};
//   float q0{1.0f};
//   K40T_LAYOUT(s, v) {
//     v("percentage", s.percentage, wire::u8);
//     v("q0", s.q0, wire::f32);
//   }
// A message writes layout() out where one entry cannot say it: bits of several members in one
// byte (wire::bit_group), a group of fields shared with other messages (a function that visits
// them), a field whose check reads another field (wire::ruled, wire::directed), or a type or kind
// with a comma outside parentheses (std::array<T, N>): the preprocessor splits entries at every
// such comma. Rules between fields in `Status extra_checks() const` go with either form.
#pragma once

#include <boost/preprocessor/cat.hpp>
#include <boost/preprocessor/seq/for_each.hpp>
#include <boost/preprocessor/tuple/size.hpp>
#include <boost/preprocessor/variadic/to_seq.hpp>

#define K40T_FIELD_MEMBER_2(name, kind)
#define K40T_FIELD_MEMBER_3(type, name, kind) type name{};
#define K40T_FIELD_MEMBER_4(type, name, kind, initial) type name{initial};
#define K40T_FIELD_MEMBER_(r, unused, entry) \
  BOOST_PP_CAT(K40T_FIELD_MEMBER_, BOOST_PP_TUPLE_SIZE(entry)) entry

#define K40T_FIELD_LINE_2(name, kind) v(#name, wire::gap, kind);
#define K40T_FIELD_LINE_3(type, name, kind) v(#name, s.name, kind);
#define K40T_FIELD_LINE_4(type, name, kind, initial) v(#name, s.name, kind);
#define K40T_FIELD_LINE_(r, unused, entry) \
  BOOST_PP_CAT(K40T_FIELD_LINE_, BOOST_PP_TUPLE_SIZE(entry)) entry

// The members, then `LAYOUT(s, v) { the lines }`: LAYOUT is the family's layout signature.
#define K40T_FIELD_LIST(LAYOUT, ...)                                                 \
  BOOST_PP_SEQ_FOR_EACH(K40T_FIELD_MEMBER_, ~, BOOST_PP_VARIADIC_TO_SEQ(__VA_ARGS__)) \
  LAYOUT(s, v) {                                                                     \
    BOOST_PP_SEQ_FOR_EACH(K40T_FIELD_LINE_, ~, BOOST_PP_VARIADIC_TO_SEQ(__VA_ARGS__)) \
  }                                                                                  \
  static_assert(true, "a K40T_FIELDS line ends with a semicolon")
