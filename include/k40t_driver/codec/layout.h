// Declarative wire layouts, shared by the pod protocol (protocol/) and DJI PSDK (psdk/).
//
// A message struct lists its fields ONCE, in wire order, each with its wire format (wire.h):
//
//   template <class S, class V>
//   static void layout(S& s, V&& v) {
//     v("code", s.code, wire::u16);                                         // response code
//     v("distance_m", s.distance_m, wire::scaled<uint16_t>(10).range(0, 6553.5, "m"));
//     v("reserved", wire::gap, wire::reserved(1));
//   }
//
// and the visitors below turn that list into the encoder, the decoder, the range checks (the
// ranges given, enum codes via to_string(), what a scaled integer or a bit field can hold, text
// widths), the size, the FieldSink description and fields() (JSON, CLI arguments, fuzz entry).
// Fields are in physical units; the tag says how they are carried.
//
// HOW TO CONVERT A POD MESSAGE (protocol/messages/*.h):
//   0. A message that is a plain list of fields declares each once with `K40T_FIELDS(...)`
//      (codec/field_list.h: members and layout() from one list); the steps below hold for its
//      entries too. A message that needs more than one field per entry writes layout() out.
//   1. Replace validate/encode/decode/fields with `K40T_MESSAGE_LAYOUT()`
//   (protocol/message_layout.h)
//      and one layout() as above. Field names are the old fields() names, in wire order.
//   2. Byte order: non-ACK payloads are little-endian (the default). ACK structs add
//      `static constexpr auto kByteOrder = &CodecOptions::ack_byte_order;` (decisions.md#a2);
//      a field the document fixes regardless uses `.little()`.
//   3. Ranges: `.range(lo, hi, unit)` on the tag; the error text is check_range()'s
//      ("field 'palette' must be 1..20, got 25"). A rule between fields (min < max) goes in
//      `Status extra_checks() const`, which validate() runs after the layout's checks.
//   4. Reserved bytes `wire::reserved(n)`; a fixed command byte `wire::fixed(code, meaning)`;
//      a two-code switch `wire::flag(on, off)`; bit fields: a small struct with its own layout()
//      of `wire::bits(shift, width)`, carried as `wire::packed8` (or, when the bits are members
//      of the message itself, `wire::bit_group(wire::in_bits(...), ...)`); a value with an "off"
//      code `wire::or_off(...)`; a struct carried inline in another message `wire::nested` (it
//      lists the shared fields in a static body(s, v)); fixed-width text `wire::Text{width,
//      terminated}`; a format of the family's own `wire::custom<C>` (wire.h).
//   5. Optional trailing bytes: kMinSize < kSize. On decode, fields that start at or after
//      kMinSize keep their defaults when the payload ends before them (a refusal ACK that is
//      the code alone, a reserved byte left off). A rule about the decoded size that depends on a
//      field (settings that must follow an OK code) goes in `Status finish_decode(size_t size)`.
//   6. Delete the .cpp bodies; keep the catalogue registration. Golden byte tests stay as they are.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

#include "k40t_driver/codec/field_visit.h"
#include "k40t_driver/codec/layout_detail.h"
#include "k40t_driver/codec/layout_validator.h"
#include "k40t_driver/codec/result.h"
#include "k40t_driver/codec/unchecked_bytes.h"
#include "k40t_driver/codec/value_checks.h"

namespace k40t::codec {

// The message's byte order is a template argument: known at compile time, each multi-byte field
// is written without a run-time test per byte (message_layout.h picks the instance once).
// Out: ByteWriter, or UncheckedWriter once the whole size has been claimed. `options`: where a
// field takes a value from the family's options (wire::directed, whose Options must be this
// Options); none: the defaults.
template <ByteOrder kOrder, class Out = ByteWriter, class Options = wire::NoOptions>
class BasicLayoutWriter {
 public:
  explicit BasicLayoutWriter(Out& w, const Options* options = nullptr) : w_(w), options_(options) {}
  template <class T, class Int>
  void operator()(const char*, const T& v, wire::Raw<Int> t) const {
    detail::write_int<Int>(w_, detail::to_raw<Int>(v, t.add), detail::order_of(kOrder, t.order));
  }
  template <class Int>
  void operator()(const char*, double v, wire::Scaled<Int> s) const {
    detail::write_int<Int>(w_, to_wire<Int>(v, s.scale), detail::order_of(kOrder, s.order));
  }
  template <class T, class Float>
  void operator()(const char*, T v, wire::Real<Float> r) const {
    detail::write_real<Float>(w_, static_cast<Float>(static_cast<double>(v) * r.scale));
  }
  template <class B, class D, class Int>
  void operator()(const char*, const wire::Switchable<B, D>& p, wire::OrOff<Int> t) const {
    const Int raw = *p.on ? to_wire<Int>(*p.value, t.value.scale) : t.off;
    detail::write_int<Int>(w_, raw, detail::order_of(kOrder, t.value.order));
  }
  template <class B, class D>
  void operator()(const char*, const wire::Switchable<B, D>& p,
                  const wire::Directed<Options>& d) const {
    const double value = static_cast<double>(*p.value);
    w_.u8(!*p.on ? d.none : value < 0 ? d.negative.value : d.positive.value);
    const double scale = detail::option(options_, d.scale);
    detail::write_int<uint16_t>(
        w_, *p.on ? to_wire<uint16_t>(std::fabs(value), scale) : uint16_t{0}, kOrder);
  }
  template <class T, class Tag, class Rule>
  void operator()(const char* name, const T& v, const wire::Ruled<Tag, Rule>& r) const {
    (*this)(name, v, r.tag);
  }
  void operator()(const char*, const std::string& v, wire::Text t) const { w_.text(v, t.width); }
  template <class T, class C>
  void operator()(const char*, const T& v, wire::Custom<C>) const {
    C::write(w_, v);
  }
  void operator()(const char*, const wire::Gap&, wire::Reserved r) const { w_.zeros(r.size); }
  void operator()(const char*, const wire::Gap&, wire::Fixed f) const { w_.u8(f.value); }
  void operator()(const char*, bool v, wire::Flag f) const { w_.u8(v ? f.on : f.off); }
  template <size_t N>
  void operator()(const char*, const std::array<uint8_t, N>& v, wire::Bytes<N>) const {
    for (uint8_t b : v) w_.u8(b);
  }
  template <class Sub, class Int>
  void operator()(const char*, const Sub& v, wire::Packed<Int>) const {
    Int word = 0;
    Sub::layout(v, detail::BitPacker<Int>{word});
    detail::write_int<Int>(w_, word, kOrder);
  }
  template <class Sub>
  void operator()(const char*, const Sub& v, wire::Nested) const {
    Sub::body(v, *this);
  }

 private:
  Out& w_;
  const Options* options_;
};
using LayoutWriter = BasicLayoutWriter<ByteOrder::kLittle>;

// Reads a layout. Fields starting at or after `optional_from` keep their default values when the
// payload has ended before them, and reserved bytes from there on may be left off. Decode errors (a
// fixed byte or a flag with another code) are kept in `failure` (the first one); without it they
// are ignored.
template <ByteOrder kOrder, class In = ByteReader, class Options = wire::NoOptions>
class BasicLayoutReader {
 public:
  explicit BasicLayoutReader(In& r, size_t optional_from = std::numeric_limits<size_t>::max(),
                             Status* failure = nullptr, const Options* options = nullptr)
      : r_(r), optional_from_(optional_from), failure_(failure), options_(options) {}
  template <class T, class Int>
  void operator()(const char*, T& v, wire::Raw<Int> t) const {
    if (absent(v)) return;
    const Int raw = detail::read_int<Int>(r_, detail::order_of(kOrder, t.order));
    v = detail::from_raw<T>(static_cast<Int>(raw & t.used_bits), t.add);
  }
  template <class Int>
  void operator()(const char*, double& v, wire::Scaled<Int> s) const {
    if (absent(v)) return;
    v = static_cast<double>(detail::read_int<Int>(r_, detail::order_of(kOrder, s.order))) / s.scale;
  }
  template <class T, class Float>
  void operator()(const char*, T& v, wire::Real<Float> r) const {
    if (absent(v)) return;
    v = static_cast<T>(static_cast<double>(detail::read_real<Float>(r_)) / r.scale);
  }
  template <class B, class D, class Int>
  void operator()(const char*, const wire::Switchable<B, D>& p, wire::OrOff<Int> t) const {
    if (absent()) return;
    const Int raw = detail::read_int<Int>(r_, detail::order_of(kOrder, t.value.order));
    *p.on = raw != t.off;
    *p.value = *p.on ? static_cast<double>(raw) / t.value.scale : 0.0;
  }
  template <class B, class D>
  void operator()(const char* name, const wire::Switchable<B, D>& p,
                  const wire::Directed<Options>& d) const {
    if (absent()) return;
    const uint8_t direction = r_.u8();
    const uint16_t magnitude = detail::read_int<uint16_t>(r_, kOrder);
    const int scale = detail::option(options_, d.scale);
    if (scale <= 0) return fail(detail::scale_error(d.scale_name, scale));
    *p.on = direction != d.none;
    if (direction == d.none) {
      *p.value = 0;
    } else if (direction == d.positive.value || direction == d.negative.value) {
      const double value = magnitude / static_cast<double>(scale);
      *p.value = direction == d.positive.value ? value : -value;
    } else if (r_.ok()) {
      fail(detail::direction_error(name, d.positive, d.negative, d.none, direction));
    }
  }
  template <class T, class Tag, class Rule>
  void operator()(const char* name, T& v, const wire::Ruled<Tag, Rule>& r) const {
    (*this)(name, v, r.tag);
  }
  void operator()(const char*, std::string& v, wire::Text t) const {
    if (absent(v)) return;
    v = r_.text(t.width);
  }
  template <class T, class C>
  void operator()(const char*, T& v, wire::Custom<C>) const {
    if (absent(v)) return;
    v = C::read(r_);
  }
  void operator()(const char*, const wire::Gap&, wire::Reserved r) const {
    // Reserved bytes past kMinSize may be left off, wholly or in part.
    const size_t required =
        r_.position() < optional_from_ ? std::min(r.size, optional_from_ - r_.position()) : 0;
    r_.skip(std::max(required, std::min(r.size, r_.remaining())));
  }
  void operator()(const char*, const wire::Gap&, wire::Fixed f) const {
    const size_t index = r_.position() + 1;  // the documents count bytes from 1
    const uint8_t got = r_.u8();
    if (r_.ok() && got != f.value) fail(detail::fixed_byte_error(index, f, got));
  }
  void operator()(const char* name, bool& v, wire::Flag f) const {
    if (absent(v)) return;
    const size_t index = r_.position() + 1;
    const uint8_t got = r_.u8();
    if (f.strict && r_.ok() && got != f.on && got != f.off)
      fail(detail::flag_error(name, index, f, got));
    v = got == f.on;
  }
  template <size_t N>
  void operator()(const char*, std::array<uint8_t, N>& v, wire::Bytes<N>) const {
    if (absent(v)) return;
    for (uint8_t& b : v) b = r_.u8();
  }
  // Sub&&: a bit_group() of the message's own members arrives as a temporary.
  template <class Sub, class Int>
  void operator()(const char*, Sub&& v, wire::Packed<Int>) const {
    if (absent()) return;
    std::decay_t<Sub>::layout(v, detail::BitUnpacker<Int>{detail::read_int<Int>(r_, kOrder)});
  }
  template <class Sub>
  void operator()(const char*, Sub& v, wire::Nested) const {
    Sub::body(v, *this);
  }

 private:
  template <class T>
  bool absent(T&) const {
    return absent();
  }
  bool absent() const {
    // The unchecked cursor is only used when the whole layout is there.
    if constexpr (std::is_same_v<In, UncheckedReader>) return false;
    return r_.remaining() == 0 && r_.position() >= optional_from_;
  }
  void fail(std::string message) const {
    if (failure_ != nullptr && failure_->is_ok()) *failure_ = Status::fail(std::move(message));
  }
  In& r_;
  size_t optional_from_;
  Status* failure_;
  const Options* options_;
};
using LayoutReader = BasicLayoutReader<ByteOrder::kLittle>;

// Counts the bytes a layout occupies (layouts are fixed-size by construction).
class LayoutSizer {
 public:
  explicit LayoutSizer(size_t& size) : size_(size) {}
  template <class T, class Int>
  void operator()(const char*, const T&, wire::Raw<Int>) const {
    size_ += sizeof(Int);
  }
  template <class Int>
  void operator()(const char*, const double&, wire::Scaled<Int>) const {
    size_ += sizeof(Int);
  }
  template <class T, class Float>
  void operator()(const char*, const T&, wire::Real<Float>) const {
    size_ += sizeof(Float);
  }
  template <class B, class D, class Int>
  void operator()(const char*, const wire::Switchable<B, D>&, wire::OrOff<Int>) const {
    size_ += sizeof(Int);
  }
  template <class B, class D, class O>
  void operator()(const char*, const wire::Switchable<B, D>&, const wire::Directed<O>&) const {
    size_ += 1 + sizeof(uint16_t);
  }
  template <class T, class Tag, class Rule>
  void operator()(const char* name, const T& v, const wire::Ruled<Tag, Rule>& r) const {
    (*this)(name, v, r.tag);
  }
  void operator()(const char*, const std::string&, wire::Text t) const { size_ += t.width; }
  template <class T, class C>
  void operator()(const char*, const T&, wire::Custom<C>) const {
    size_ += C::kSize;
  }
  void operator()(const char*, const wire::Gap&, wire::Reserved r) const { size_ += r.size; }
  void operator()(const char*, const wire::Gap&, wire::Fixed) const { size_ += 1; }
  void operator()(const char*, const bool&, wire::Flag) const { size_ += 1; }
  template <size_t N>
  void operator()(const char*, const std::array<uint8_t, N>&, wire::Bytes<N>) const {
    size_ += N;
  }
  template <class Sub, class Int>
  void operator()(const char*, const Sub&, wire::Packed<Int>) const {
    size_ += sizeof(Int);
  }
  template <class Sub>
  void operator()(const char*, const Sub& v, wire::Nested) const {
    Sub::body(v, *this);
  }

 private:
  size_t& size_;
};

// Hands every field (bit fields and nested structs flattened, no reserved or fixed bytes) to a
// visitor v(name, field): what the message contract's fields() does, for JSON, CLI arguments,
// FieldSink and the generic tests.
template <class V>
class FieldLister {
 public:
  explicit FieldLister(V& v) : v_(v) {}
  template <class T, class Tag>
  void operator()(const char* name, T& value, Tag) const {
    v_(name, value);
  }
  template <class Tag>
  void operator()(const char*, const wire::Gap&, Tag) const {}
  template <class Sub, class Int>
  void operator()(const char*, Sub& v, wire::Packed<Int>) const {
    std::decay_t<Sub>::layout(v, *this);
  }
  template <class... T, class Int>
  void operator()(const char*, const wire::BitGroup<T...>& group, wire::Packed<Int>) const {
    wire::BitGroup<T...>::layout(group, *this);
  }
  template <class B, class D, class Tag>
  void operator()(const char*, const wire::Switchable<B, D>& p, Tag) const {
    v_(p.on_name, *p.on);
    v_(p.value_name, *p.value);
  }
  template <class Sub>
  void operator()(const char*, Sub& v, wire::Nested) const {
    std::decay_t<Sub>::body(v, *this);
  }

 private:
  V& v_;
};

// Reports every field to a FieldSink (FieldLister + the typed adapter of field_visit.h).
class LayoutSink {
 public:
  explicit LayoutSink(FieldSink& sink) : sink_(sink) {}
  template <class T, class Tag>
  void operator()(const char* name, const T& v, Tag tag) const {
    detail::SinkAdapter adapter{sink_};
    FieldLister<detail::SinkAdapter>{adapter}(name, v, tag);
  }

 private:
  FieldSink& sink_;
};

}  // namespace k40t::codec
