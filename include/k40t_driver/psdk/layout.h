// Declarative wire layouts for PSDK command structs.
//
// A fixed-layout struct lists its fields once, in wire order, each with its wire format:
//
//   template <class S, class V>
//   static void layout(S& s, V&& v) {
//     v("pitch_rate_deg_s", s.pitch_rate_deg_s, wire::scaled<int16_t>(10));  // int16, 0.1 deg/s
//     v("action", s.action, wire::u8);                                     // enum on one byte
//   }
//
// and the visitors below turn that list into the encoder, the decoder, the generic range checks
// (enum codes, what a scaled integer can hold, text widths, bit widths), the size and the
// FieldSink description. Fields are in physical units; the wire tag says how they are carried.
// Everything is little-endian (section 2.1 and 3.3.9).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

#include "k40t_driver/protocol/byte_io.h"
#include "k40t_driver/protocol/field_visit.h"
#include "k40t_driver/protocol/message.h"

namespace k40t::psdk {

using protocol::ByteReader;
using protocol::ByteWriter;
using protocol::FieldSink;

namespace wire {
// An integer on the wire; the field is the same integer type, a bool, or an enum.
template <class Int>
struct Raw {};
// An integer on the wire carrying physical value * scale; the field is a double.
template <class Int>
struct Scaled {
  double scale;
};
// An IEEE float/double on the wire carrying physical value * scale; the field is float/double.
template <class Float>
struct Real {
  double scale = 1.0;
};
// Fixed-width text, NUL-terminated when shorter than the width.
struct Text {
  size_t width;
};
// Raw bytes; the field is std::array<uint8_t, N>.
template <size_t N>
struct Bytes {};
// One integer holding bit fields; the field is a struct whose own layout() uses Bits.
template <class Int>
struct Packed {};
// Reserved bytes, sent as zero and skipped on reception; they have no field, so layout() passes
// `wire::gap` as the value: v("reserved", wire::gap, wire::Reserved{1}).
struct Gap {};
inline constexpr Gap gap{};
struct Reserved {
  size_t size;
};
// Inside a Packed struct: `width` bits starting at bit `shift`.
struct Bits {
  unsigned shift;
  unsigned width;
};

inline constexpr Raw<uint8_t> u8{};
inline constexpr Raw<uint16_t> u16{};
inline constexpr Raw<uint32_t> u32{};
inline constexpr Raw<int16_t> i16{};
inline constexpr Raw<int32_t> i32{};
inline constexpr Real<float> f32{};
inline constexpr Real<double> f64{};
inline constexpr Packed<uint8_t> packed8{};
inline constexpr Packed<uint16_t> packed16{};
template <class Int>
constexpr Scaled<Int> scaled(double scale) {
  return {scale};
}
constexpr Real<float> f32_scaled(double scale) {
  return {scale};
}
constexpr Bits bit(unsigned n) {
  return {n, 1};
}
constexpr Bits bits(unsigned shift, unsigned width) {
  return {shift, width};
}
}  // namespace wire

namespace detail {

template <class Int>
void write_int(ByteWriter& w, Int v) {
  if constexpr (sizeof(Int) == 1)
    w.u8(static_cast<uint8_t>(v));
  else if constexpr (sizeof(Int) == 2)
    w.u16(static_cast<uint16_t>(v));
  else if constexpr (sizeof(Int) == 4)
    w.u32(static_cast<uint32_t>(v));
  else
    w.u64(static_cast<uint64_t>(v));
}

template <class Int>
Int read_int(ByteReader& r) {
  if constexpr (sizeof(Int) == 1)
    return static_cast<Int>(r.u8());
  else if constexpr (sizeof(Int) == 2)
    return static_cast<Int>(r.u16());
  else if constexpr (sizeof(Int) == 4)
    return static_cast<Int>(r.u32());
  else
    return static_cast<Int>(r.u64());
}

template <class Int, class T>
Int to_raw(const T& v) {
  if constexpr (std::is_same_v<T, bool>)
    return v ? Int{1} : Int{0};
  else if constexpr (std::is_enum_v<T>)
    return static_cast<Int>(static_cast<std::underlying_type_t<T>>(v));
  else
    return static_cast<Int>(v);
}

template <class T, class Int>
T from_raw(Int raw) {
  if constexpr (std::is_same_v<T, bool>)
    return raw != 0;
  else
    return static_cast<T>(raw);
}

template <class Float>
void write_real(ByteWriter& w, Float v) {
  if constexpr (sizeof(Float) == 4) {
    uint32_t u = 0;
    std::memcpy(&u, &v, sizeof(u));
    w.u32(u);
  } else {
    uint64_t u = 0;
    std::memcpy(&u, &v, sizeof(u));
    w.u64(u);
  }
}

template <class Float>
Float read_real(ByteReader& r) {
  Float v{};
  if constexpr (sizeof(Float) == 4) {
    const uint32_t u = r.u32();
    std::memcpy(&v, &u, sizeof(v));
  } else {
    const uint64_t u = r.u64();
    std::memcpy(&v, &u, sizeof(v));
  }
  return v;
}

template <class Int>
constexpr Int bit_mask(unsigned width) {
  return width >= sizeof(Int) * 8 ? static_cast<Int>(~Int{0})
                                  : static_cast<Int>((Int{1} << width) - 1);
}

template <class Int>
struct BitPacker {
  Int& word;
  template <class T>
  void operator()(const char*, const T& v, wire::Bits b) const {
    word = static_cast<Int>(word | ((to_raw<Int>(v) & bit_mask<Int>(b.width)) << b.shift));
  }
};

template <class Int>
struct BitUnpacker {
  Int word;
  template <class T>
  void operator()(const char*, T& v, wire::Bits b) const {
    v = from_raw<T>(static_cast<Int>((word >> b.shift) & bit_mask<Int>(b.width)));
  }
};

}  // namespace detail

class LayoutWriter {
 public:
  explicit LayoutWriter(ByteWriter& w) : w_(w) {}
  template <class T, class Int>
  void operator()(const char*, const T& v, wire::Raw<Int>) const {
    detail::write_int<Int>(w_, detail::to_raw<Int>(v));
  }
  template <class Int>
  void operator()(const char*, double v, wire::Scaled<Int> s) const {
    detail::write_int<Int>(w_, protocol::to_wire<Int>(v, s.scale));
  }
  template <class T, class Float>
  void operator()(const char*, T v, wire::Real<Float> r) const {
    detail::write_real<Float>(w_, static_cast<Float>(static_cast<double>(v) * r.scale));
  }
  void operator()(const char*, const std::string& v, wire::Text t) const { w_.text(v, t.width); }
  void operator()(const char*, const wire::Gap&, wire::Reserved r) const { w_.zeros(r.size); }
  template <size_t N>
  void operator()(const char*, const std::array<uint8_t, N>& v, wire::Bytes<N>) const {
    for (uint8_t b : v) w_.u8(b);
  }
  template <class Sub, class Int>
  void operator()(const char*, const Sub& v, wire::Packed<Int>) const {
    Int word = 0;
    Sub::layout(v, detail::BitPacker<Int>{word});
    detail::write_int<Int>(w_, word);
  }

 private:
  ByteWriter& w_;
};

class LayoutReader {
 public:
  explicit LayoutReader(ByteReader& r) : r_(r) {}
  template <class T, class Int>
  void operator()(const char*, T& v, wire::Raw<Int>) const {
    v = detail::from_raw<T>(detail::read_int<Int>(r_));
  }
  template <class Int>
  void operator()(const char*, double& v, wire::Scaled<Int> s) const {
    v = static_cast<double>(detail::read_int<Int>(r_)) / s.scale;
  }
  template <class T, class Float>
  void operator()(const char*, T& v, wire::Real<Float> r) const {
    v = static_cast<T>(static_cast<double>(detail::read_real<Float>(r_)) / r.scale);
  }
  void operator()(const char*, std::string& v, wire::Text t) const { v = r_.text(t.width); }
  void operator()(const char*, const wire::Gap&, wire::Reserved r) const { r_.skip(r.size); }
  template <size_t N>
  void operator()(const char*, std::array<uint8_t, N>& v, wire::Bytes<N>) const {
    for (uint8_t& b : v) b = r_.u8();
  }
  template <class Sub, class Int>
  void operator()(const char*, Sub& v, wire::Packed<Int>) const {
    Sub::layout(v, detail::BitUnpacker<Int>{detail::read_int<Int>(r_)});
  }

 private:
  ByteReader& r_;
};

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
  void operator()(const char*, const std::string&, wire::Text t) const { size_ += t.width; }
  void operator()(const char*, const wire::Gap&, wire::Reserved r) const { size_ += r.size; }
  template <size_t N>
  void operator()(const char*, const std::array<uint8_t, N>&, wire::Bytes<N>) const {
    size_ += N;
  }
  template <class Sub, class Int>
  void operator()(const char*, const Sub&, wire::Packed<Int>) const {
    size_ += sizeof(Int);
  }

 private:
  size_t& size_;
};

// The checks every layout implies, before the struct's own validate(): enum codes the document
// defines, values a scaled integer or a float can carry, text that fits with its terminator,
// bit fields that fit their width. Keeps the first failure.
class LayoutValidator {
 public:
  explicit LayoutValidator(Status& result) : result_(result) {}
  template <class T, class Int>
  void operator()(const char* name, const T& v, wire::Raw<Int>) const {
    if constexpr (std::is_enum_v<T>) keep(protocol::check_enum(name, v));
  }
  template <class Int>
  void operator()(const char* name, double v, wire::Scaled<Int> s) const {
    keep(protocol::check_range(name, v, std::numeric_limits<Int>::min() / s.scale,
                               std::numeric_limits<Int>::max() / s.scale));
  }
  template <class T, class Float>
  void operator()(const char* name, T v, wire::Real<Float> r) const {
    const double limit = static_cast<double>(std::numeric_limits<Float>::max()) / r.scale;
    keep(protocol::check_range(name, static_cast<double>(v), -limit, limit));
  }
  // Width includes the terminating NUL: a full-width name would not be terminated, which the
  // document's "with \0 as the ending character" rules out.
  void operator()(const char* name, const std::string& v, wire::Text t) const {
    keep(protocol::check_text(name, v, t.width - 1));
  }
  void operator()(const char*, const wire::Gap&, wire::Reserved) const {}
  template <size_t N>
  void operator()(const char*, const std::array<uint8_t, N>&, wire::Bytes<N>) const {}
  template <class Sub, class Int>
  void operator()(const char*, const Sub& v, wire::Packed<Int>) const {
    Sub::layout(v, *this);
  }
  template <class T>
  void operator()(const char* name, const T& v, wire::Bits b) const {
    if constexpr (std::is_enum_v<T>) keep(protocol::check_enum(name, v));
    const uint64_t raw = detail::to_raw<uint64_t>(v);
    keep(protocol::check_range(name, static_cast<int64_t>(raw), 0,
                               static_cast<int64_t>(detail::bit_mask<uint64_t>(b.width))));
  }

 private:
  void keep(const Status& s) const {
    if (result_.is_ok() && !s.is_ok()) result_ = s;
  }
  Status& result_;
};

// Reports every field (bit fields of packed words one by one) to a FieldSink.
class LayoutSink {
 public:
  explicit LayoutSink(FieldSink& sink) : sink_(sink) {}
  template <class T, class Tag>
  void operator()(const char* name, const T& v, Tag) const {
    protocol::detail::SinkAdapter{sink_}(name, v);
  }
  void operator()(const char*, const wire::Gap&, wire::Reserved) const {}
  template <class Sub, class Int>
  void operator()(const char*, const Sub& v, wire::Packed<Int>) const {
    Sub::layout(v, *this);
  }

 private:
  FieldSink& sink_;
};

}  // namespace k40t::psdk
