// A pod message described by a layout() (codec/layout.h) meets message.h's contract through
// K40T_MESSAGE_LAYOUT(), written once in the struct that has the layout():
//
//   struct SbusRangeRequest {
//     kId, kName, kSection, kDirection, kSize, kMinSize ...
//     uint16_t max_value = 1811;
//     uint16_t min_value = 172;
//     K40T_MESSAGE_LAYOUT()
//     template <class S, class V>
//     static void layout(S& s, V&& v) { ... }
//     Status extra_checks() const;   // optional: rules between fields
//   };
//
// The macro defines validate() (the layout's checks, then extra_checks() if the struct has one),
// validate(options) (the same and what the options decide, e.g. 0x000012's scaled magnitudes),
// encode(), decode() and fields(). Byte order: the struct's
// `static constexpr ByteOrder CodecOptions::* kByteOrder` if it has one (ACKs:
// &CodecOptions::ack_byte_order, docs/protocol/decisions.md#a2), else little-endian (section 2.1).
// Fields from kMinSize on are optional on decode (they keep their defaults when the payload ends);
// `Status finish_decode(size_t payload_size)`, if the struct has one, runs after a decode.
#pragma once

#include <type_traits>
#include <utility>

#include "k40t_driver/codec/field_list.h"
#include "k40t_driver/codec/layout.h"
#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/message.h"

namespace k40t::protocol {

namespace wire = codec::wire;

namespace layout_detail {
template <class T, class = void>
struct HasByteOrder : std::false_type {};
template <class T>
struct HasByteOrder<T, std::void_t<decltype(T::kByteOrder)>> : std::true_type {};
template <class T, class = void>
struct HasExtraChecks : std::false_type {};
template <class T>
struct HasExtraChecks<T, std::void_t<decltype(std::declval<const T&>().extra_checks())>>
    : std::true_type {};

template <class T, class = void>
struct HasFinishDecode : std::false_type {};
template <class T>
struct HasFinishDecode<T, std::void_t<decltype(std::declval<T&>().finish_decode(size_t{}))>>
    : std::true_type {};

// Calls visit(std::integral_constant<ByteOrder, order>) with the struct's byte order: little-endian
// unless it has a kByteOrder (then the option it names), chosen once per message, not per byte.
template <class T, class Visit>
void with_byte_order(const CodecOptions& o, Visit&& visit) {
  if constexpr (HasByteOrder<T>::value) {
    if (o.*T::kByteOrder == ByteOrder::kBig) {
      visit(std::integral_constant<ByteOrder, ByteOrder::kBig>{});
      return;
    }
  }
  visit(std::integral_constant<ByteOrder, ByteOrder::kLittle>{});
}

// `options`: set when encoding, to also check what depends on them (codec/layout_validator.h).
template <class T>
[[gnu::flatten]] Status validate(const T& m, const CodecOptions* options = nullptr) {
  Status result = Status::ok();
  T::layout(m, codec::LayoutValidator(result, options));
  if constexpr (HasExtraChecks<T>::value) {
    if (result.is_ok()) return m.extra_checks();
  }
  return result;
}

// Both claim the layout's kSize bytes once and then write or read them without a check per byte
// (codec/unchecked_bytes.h); a shorter payload (optional trailing fields) is read checked. That
// kSize is what the layout occupies is a unit test over every message (test_message_layouts.cpp).
// flatten: the layout and its visitor are inlined here, so the cursor lives in a register instead
// of being reloaded from memory after every byte stored (a byte store may alias anything).
template <class T>
[[gnu::flatten]] void encode(const T& m, ByteWriter& w, const CodecOptions& o) {
  uint8_t* out = w.claim(T::kSize);
  if (out == nullptr) return;  // w has failed: encode_payload reports the overflow
  codec::UncheckedWriter cursor(out);
  with_byte_order<T>(o, [&](auto order) {
    T::layout(
        m, codec::BasicLayoutWriter<decltype(order)::value, codec::UncheckedWriter, CodecOptions>(
               cursor, &o));
  });
}

template <class T>
inline Status decode_body(T& m, ByteReader& r, const CodecOptions& o) {
  Status failure = Status::ok();
  const size_t size = r.remaining();
  constexpr size_t full = T::kSize;
  with_byte_order<T>(o, [&](auto order) {
    constexpr ByteOrder kOrder = decltype(order)::value;
    if (size >= full) {
      const size_t start = r.position();
      codec::UncheckedReader cursor(r.claim(full), full, start);
      T::layout(m, codec::BasicLayoutReader<kOrder, codec::UncheckedReader, CodecOptions>(
                       cursor, T::kMinSize, &failure, &o));
    } else {
      T::layout(m, codec::BasicLayoutReader<kOrder, ByteReader, CodecOptions>(r, T::kMinSize,
                                                                              &failure, &o));
    }
  });
  if constexpr (HasFinishDecode<T>::value) {
    if (failure.is_ok()) return m.finish_decode(size);
  }
  return failure;
}

// decode() of a layout of at most this many bytes (a response code and one value: the laser
// distance ACK, the bare ACK) is inlined into decode_payload: for so little work the call and the
// Status it returns through memory cost as much again (bench_codec: LaserRangeAck decode 4.0 -> 2.0
// ns). Longer layouts measured faster as one call (ThermalStatus decode 3.0 ns as a call, 12 ns
// inlined). validate() and encode() stay one call: the same split made the long ones slower
// (ThermalSettingsAck encode 59 -> 90 ns), and inlining the laser ACK's encode made it slower
// (18.5 -> 19-21 ns). What made that encode slower than the hand-written one was validate()'s call
// to check_range per field; the validator now tests the range itself (codec/layout_validator.h),
// and GCC inlines the laser ACK's validate() on its own (encode 18.6 -> 16.3 ns).
constexpr size_t kInlineLayoutBytes = 4;

template <class T>
[[gnu::flatten]] Status decode_call(T& m, ByteReader& r, const CodecOptions& o) {
  return decode_body(m, r, o);
}

// flatten is on the two wrappers, not on the body: GCC drops it on a function that is itself
// always inlined (with it on the body, ThermalStatus decode went 2.8 -> 12 ns).
template <class T>
[[gnu::flatten, gnu::always_inline]] inline Status decode_inline(T& m, ByteReader& r,
                                                                 const CodecOptions& o) {
  return decode_body(m, r, o);
}

template <class T>
inline Status decode(T& m, ByteReader& r, const CodecOptions& o) {
  if constexpr (T::kSize <= kInlineLayoutBytes) return decode_inline(m, r, o);
  return decode_call(m, r, o);
}
}  // namespace layout_detail

}  // namespace k40t::protocol

// The members message.h's contract asks for, from the struct's layout().
#define K40T_MESSAGE_LAYOUT()                                                                   \
  ::k40t::Status validate() const {                                                             \
    return ::k40t::protocol::layout_detail::validate(*this);                                    \
  }                                                                                             \
  ::k40t::Status validate(const ::k40t::protocol::CodecOptions& o) const {                      \
    return ::k40t::protocol::layout_detail::validate(*this, &o);                                \
  }                                                                                             \
  void encode(::k40t::protocol::ByteWriter& w, const ::k40t::protocol::CodecOptions& o) const { \
    ::k40t::protocol::layout_detail::encode(*this, w, o);                                       \
  }                                                                                             \
  ::k40t::Status decode(::k40t::protocol::ByteReader& r,                                        \
                        const ::k40t::protocol::CodecOptions& o) {                              \
    return ::k40t::protocol::layout_detail::decode(*this, r, o);                                \
  }                                                                                             \
  template <class Self, class V>                                                                \
  static void fields(Self& self, V&& v) {                                                       \
    layout(self, ::k40t::codec::FieldLister<std::remove_reference_t<V>>(v));                    \
  }

// K40T_MESSAGE_LAYOUT() and the layout's signature in one line; the body follows:
//   K40T_LAYOUT(s, v) {
//     v("x_px", s.x_px, wire::u16.range(0, kThermalPictureWidth));
//   }
// `s` is the message (const when validating or encoding), `v` the visitor (codec/layout.h).
#define K40T_LAYOUT(s, v)       \
  K40T_MESSAGE_LAYOUT()         \
  template <class S_, class V_> \
  static void layout([[maybe_unused]] S_& s, V_&& v)

// A message whose payload is its fields in order, each declared once (codec/field_list.h):
//   K40T_FIELDS((ResponseCode, code, wire::response_code), (uint8_t, mode, wire::u8));
#define K40T_FIELDS(...) K40T_FIELD_LIST(K40T_LAYOUT, __VA_ARGS__)
