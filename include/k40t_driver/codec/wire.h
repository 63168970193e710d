// The wire formats a declarative layout names (see layout.h for how a message uses them).
//
// Each tag says how one field is carried; the optional parts are set with chained constexpr
// calls, so a layout line reads like the document's table row:
//
//   v("palette", s.palette, wire::u8.range(1, 20))                      // byte, 1..20
//   v("distance_m", s.distance_m, wire::scaled<uint16_t>(10))           // uint16, 0.1 m
//   v("pitch_deg", s.pitch_deg, wire::scaled<int16_t>(100).range(-90, 30, "deg"))
//   v("yaw_channel", s.yaw_channel, wire::u8.offset(1).range(1, 16))    // wire 0..15 = 1..16
//   v("reserved", wire::gap, wire::reserved(2))                         // two zero bytes
//   v("command", wire::gap, wire::fixed(0x01, "read all settings"))     // a fixed byte
//   v("command", wire::gap, wire::command(0x01))                        // the same, "command code"
//   v("enable", s.enable, wire::on_off)                                 // 0 off / 1 on
//   v("ae_lock_on", s.ae_lock_on, wire::flag(0x01, 0x02))               // on / off codes
//   v("ae_lock_on", s.ae_lock_on, wire::report_flag(0x01, 0x02))        // the same, in a report
//   v("high_alarm", wire::switchable("high_alarm_on", s.high_alarm_on, "high_alarm_degC",
//                                    s.high_alarm_degC),
//     wire::or_off(wire::scaled<int16_t>(10).range(-100, 500, "degC"), int16_t{-2732}))
//   v("pitch", wire::switchable("pitch_move", s.pitch_move, "pitch_deg", s.pitch_deg),
//     wire::directed({0, "up"}, {1, "down"}, 2, &CodecOptions::angle_command_scale,
//                    "angle_command_scale")
//         .range(-90, 30, "deg (up positive)"))                      // direction byte + |value|
//   v("zoom_x", s.zoom_x, wire::ruled(wire::scaled<uint16_t>(10), [&s](const char* name,
//     double zoom) { return check_zoom(name, s.lens, zoom); }))     // a check that needs s.lens
#pragma once

#include <cstddef>
#include <cstdint>
#include <tuple>

#include "k40t_driver/codec/byte_io.h"

namespace k40t::codec {

namespace wire {

// Where a multi-byte field takes its byte order from: the message (its kByteOrder, see layout.h)
// or a fixed order the document states for this field alone.
enum class Order : uint8_t { kMessage, kLittle, kBig };

// The document's range of a field, in the field's own (physical) unit. Unset: the wire type's
// own limits are the only check.
struct Limits {
  bool set = false;
  double lo = 0;
  double hi = 0;
  const char* unit = "";
};

// An integer on the wire; the field is an integer (wire value + offset), a bool or an enum.
template <class Int>
struct Raw {
  Limits limits{};
  int64_t add = 0;  // field = wire + add (channel numbers 1..16 carried as 0..15)
  Order order = Order::kMessage;
  bool any_code = false;  // an enum whose undefined codes are still sent (response codes)
  uint64_t used_bits = ~uint64_t{0};  // the bits that carry the value; the rest are reserved
  constexpr Raw range(double lo, double hi, const char* unit = "") const {
    Raw r = *this;
    r.limits = {true, lo, hi, unit};
    return r;
  }
  constexpr Raw offset(int64_t n) const {
    Raw r = *this;
    r.add = n;
    return r;
  }
  constexpr Raw little() const {
    Raw r = *this;
    r.order = Order::kLittle;
    return r;
  }
  // Only `bits` carry the value: the others are ignored on receive.
  constexpr Raw mask(uint64_t bits) const {
    Raw r = *this;
    r.used_bits = bits;
    return r;
  }
};
// An integer on the wire carrying physical value * scale; the field is a double.
template <class Int>
struct Scaled {
  double scale;
  Limits limits{};
  Order order = Order::kMessage;
  constexpr Scaled range(double lo, double hi, const char* unit = "") const {
    Scaled r = *this;
    r.limits = {true, lo, hi, unit};
    return r;
  }
  constexpr Scaled little() const {
    Scaled r = *this;
    r.order = Order::kLittle;
    return r;
  }
};
// An IEEE float/double on the wire carrying physical value * scale; the field is float/double.
template <class Float>
struct Real {
  double scale = 1.0;
};
// Fixed-width text, NUL-padded. `terminated`: the width includes a NUL that must stay (PSDK
// names); otherwise the text may fill the whole width.
struct Text {
  size_t width;
  bool terminated = true;
};
// A format only one message family has (the camera's IPv4 addresses: dotted text in the struct,
// four bytes on the wire), given by a struct C of the family's own:
//   static constexpr size_t kSize;                          // bytes on the wire
//   template <class Out> static void write(Out&, const T&);  // Out has u8()
//   template <class In> static T read(In&);                  // In has u8()
//   static Status check(const char* field, const T&);        // validation, naming the field
template <class C>
struct Custom {};
// Raw bytes; the field is std::array<uint8_t, N>.
template <size_t N>
struct Bytes {};
// One integer holding bit fields; the field is a struct whose own layout() uses Bits.
template <class Int>
struct Packed {};
// A struct carried inline (e.g. the SBUS values inside their ACK): its static body(s, v) lists
// the fields it shares (its layout() is body() plus its own reserved bytes).
struct Nested {};
// The options of a family that has none (the PSDK): what the layout visitors get by default.
struct NoOptions {};

// Bytes with no field of their own: layout() passes `wire::gap` as the value.
struct Gap {};
inline constexpr Gap gap{};
// Reserved bytes, sent as zero and skipped on reception.
struct Reserved {
  size_t size;
};
// A byte whose only documented value is `value` ("0x01 read all settings"): sent as is, and any
// other value fails decoding, naming the byte.
struct Fixed {
  uint8_t value;
  const char* meaning;
  bool decimal = false;  // "byte 1 must be the command code 1, got 2" rather than hex
};
// A bool carried as one of two codes; any other code fails decoding, naming the field (or, when
// `decimal`, the byte: "byte 1 must be 0 (off) or 1 (on), got 2").
struct Flag {
  uint8_t on;
  uint8_t off;
  bool decimal = false;
  bool strict = true;  // false: a report, where any code but `on` reads as off (report_flag)
};
// Inside a Packed struct: `width` bits starting at bit `shift`; `inverted`: a 1-bit bool that
// is 0 on the wire when true.
struct Bits {
  unsigned shift;
  unsigned width;
  bool inverted = false;
  Limits limits{};
  constexpr Bits range(double lo, double hi, const char* unit = "") const {
    Bits r = *this;
    r.limits = {true, lo, hi, unit};
    return r;
  }
};

// Scaled, or the wire value `off` for "switched off" (the thermal alarm limits: -2732 = off). The
// field is a Switchable: the message's bool and double, listed as two fields.
template <class Int>
struct OrOff {
  Scaled<Int> value;
  Int off;
};
template <class B, class D>
struct Switchable {
  const char* on_name;
  B* on;
  const char* value_name;
  D* value;
};

// A signed value carried as a direction byte and a uint16 magnitude, |value| x the scale a member
// of the family's options holds (the pod's CodecOptions::angle_command_scale for the gimbal angle
// request 0x000012, docs/protocol/decisions.md#a4). The options type is a template argument so
// the codec knows no family's options; the layout visitors are given the same type.
// The field is a Switchable: the bool off is the direction code `none` ("no movement", magnitude
// sent as 0, value read as 0). The range applies to the value whether or not it moves.
struct Code {
  uint8_t value;
  const char* meaning;  // for decode errors: "0 (up), 1 (down) or 2 (no movement)"
};
template <class Options>
struct Directed {
  Code positive;  // the direction code of a positive value
  Code negative;
  uint8_t none;
  int Options::*scale;
  const char* scale_name;  // for the error when the option is not positive
  Limits limits{};
  constexpr Directed range(double lo, double hi, const char* unit = "") const {
    Directed r = *this;
    r.limits = {true, lo, hi, unit};
    return r;
  }
};

// Another tag whose checks are replaced by `rule(name, value)`, a Status-returning callable: for a
// range that depends on another field of the message (the aim zoom depends on the lens). The rule
// is only called while every field before it has passed.
template <class Tag, class Rule>
struct Ruled {
  Tag tag;
  Rule rule;
};

// Bit fields of one integer whose fields are members of the message itself (not of a sub-struct):
//   v("config", wire::bit_group(wire::in_bits("measurement_on", s.measurement_on,
//                                             wire::inverted_bit(0)), ...), wire::packed8)
template <class T>
struct BitRef {
  const char* name;
  T* value;
  Bits bits;
};
template <class... T>
struct BitGroup {
  std::tuple<BitRef<T>...> refs;
  template <class G, class V>
  static void layout(G& group, V&& v) {
    std::apply([&v](const auto&... r) { (v(r.name, *r.value, r.bits), ...); }, group.refs);
  }
};

inline constexpr Raw<uint8_t> u8{};
// The pod's 2-byte response code: an enum, but a code the document does not define is reported
// and may be sent (the simulator's fault injection), so it is not validated.
inline constexpr Raw<uint16_t> response_code{{}, 0, Order::kMessage, true};
inline constexpr Raw<int8_t> i8{};
inline constexpr Raw<uint16_t> u16{};
inline constexpr Raw<uint32_t> u32{};
inline constexpr Raw<uint64_t> u64{};
inline constexpr Raw<int16_t> i16{};
inline constexpr Raw<int32_t> i32{};
inline constexpr Raw<int64_t> i64{};
inline constexpr Real<float> f32{};
inline constexpr Real<double> f64{};
inline constexpr Packed<uint8_t> packed8{};
inline constexpr Packed<uint16_t> packed16{};
inline constexpr Nested nested{};
template <class C>
inline constexpr Custom<C> custom{};
template <class Int>
constexpr Scaled<Int> scaled(double scale) {
  return {scale};
}
constexpr Real<float> f32_scaled(double scale) {
  return {scale};
}
constexpr Reserved reserved(size_t size) {
  return {size};
}
constexpr Fixed fixed(uint8_t value, const char* meaning) {
  return {value, meaning};
}
constexpr Fixed command(uint8_t value) {
  return {value, "the command code", true};
}
constexpr Flag flag(uint8_t on, uint8_t off) {
  return {on, off};
}
inline constexpr Flag on_off{1, 0, true};  // "0 off / 1 on"
// A switch in a report: sent as `on` / `off`, but read as what the pod says, `on` or not, without
// failing on another code (a status must not be lost over one odd byte).
constexpr Flag report_flag(uint8_t on, uint8_t off) {
  return {on, off, false, false};
}
constexpr Bits bit(unsigned n) {
  return {n, 1};
}
constexpr Bits inverted_bit(unsigned n) {
  return {n, 1, true};
}
constexpr Bits bits(unsigned shift, unsigned width) {
  return {shift, width};
}
template <class Int>
constexpr OrOff<Int> or_off(Scaled<Int> value, Int off) {
  return {value, off};
}
template <class Options>
constexpr Directed<Options> directed(Code positive, Code negative, uint8_t none,
                                     int Options::*scale, const char* scale_name) {
  return {positive, negative, none, scale, scale_name};
}
template <class Tag, class Rule>
constexpr Ruled<Tag, Rule> ruled(Tag tag, Rule rule) {
  return {tag, rule};
}
template <class B, class D>
constexpr Switchable<B, D> switchable(const char* on_name, B& on, const char* value_name,
                                      D& value) {
  return {on_name, &on, value_name, &value};
}
template <class T>
constexpr BitRef<T> in_bits(const char* name, T& value, Bits bits) {
  return {name, &value, bits};
}
template <class... T>
constexpr BitGroup<T...> bit_group(BitRef<T>... refs) {
  return {{refs...}};
}
}  // namespace wire

}  // namespace k40t::codec
