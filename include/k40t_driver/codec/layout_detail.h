// Integer/float conversion and bit packing helpers of the layout visitors (layout.h).
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/codec/wire.h"

namespace k40t::codec::detail {

constexpr ByteOrder order_of(ByteOrder message, wire::Order field) {
  return field == wire::Order::kMessage  ? message
         : field == wire::Order::kLittle ? ByteOrder::kLittle
                                         : ByteOrder::kBig;
}

// Out/In: ByteWriter/ByteReader, or the unchecked cursors of unchecked_bytes.h.
template <class Int, class Out>
void write_int(Out& w, Int v, ByteOrder order) {
  if constexpr (sizeof(Int) == 1)
    w.u8(static_cast<uint8_t>(v));
  else if constexpr (sizeof(Int) == 2)
    w.u16(static_cast<uint16_t>(v), order);
  else if constexpr (sizeof(Int) == 4)
    w.u32(static_cast<uint32_t>(v), order);
  else
    w.u64(static_cast<uint64_t>(v), order);
}

template <class Int, class In>
Int read_int(In& r, ByteOrder order) {
  if constexpr (sizeof(Int) == 1)
    return static_cast<Int>(r.u8());
  else if constexpr (sizeof(Int) == 2)
    return static_cast<Int>(r.u16(order));
  else if constexpr (sizeof(Int) == 4)
    return static_cast<Int>(r.u32(order));
  else
    return static_cast<Int>(r.u64(order));
}

template <class Int, class T>
Int to_raw(const T& v, int64_t add = 0) {
  if constexpr (std::is_same_v<T, bool>)
    return v ? Int{1} : Int{0};
  else if constexpr (std::is_enum_v<T>)
    return static_cast<Int>(static_cast<std::underlying_type_t<T>>(v));
  else
    return static_cast<Int>(static_cast<int64_t>(v) - add);
}

template <class T, class Int>
T from_raw(Int raw, int64_t add = 0) {
  if constexpr (std::is_same_v<T, bool>)
    return raw != 0;
  else if constexpr (std::is_enum_v<T>)
    return static_cast<T>(raw);
  else
    return static_cast<T>(static_cast<int64_t>(raw) + add);
}

template <class Float, class Out>
void write_real(Out& w, Float v) {
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

template <class Float, class In>
Float read_real(In& r) {
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
    Int raw = to_raw<Int>(v);
    if (b.inverted) raw = raw ? 0 : 1;
    word = static_cast<Int>(word | ((raw & bit_mask<Int>(b.width)) << b.shift));
  }
};

template <class Int>
struct BitUnpacker {
  Int word;
  template <class T>
  void operator()(const char*, T& v, wire::Bits b) const {
    Int raw = static_cast<Int>((word >> b.shift) & bit_mask<Int>(b.width));
    if (b.inverted) raw = raw ? 0 : 1;
    v = from_raw<T>(raw);
  }
};

// The value of an options member a field takes (the defaults when no options were given).
template <class Options>
int option(const Options* options, int Options::*member) {
  static const Options kDefaults{};
  return options != nullptr ? options->*member : kDefaults.*member;
}
// "angle_command_scale must be positive, got 0"
std::string scale_error(const char* scale_name, int scale);
// A directed value at `scale` must be carried by the uint16 magnitude (a larger one would saturate
// and move the gimbal to another angle): "field 'yaw_deg' 180 x angle_command_scale 1000 = 180000
// does not fit the 16-bit magnitude (at most 65535): angle_command_scale must be 1..364".
Status check_magnitude(const char* field, double value, const char* scale_name,
                       const wire::Limits& limits, int scale);
// "pitch direction byte must be 0 (up), 1 (down) or 2 (no movement), got 3"
std::string direction_error(const char* field, const wire::Code& positive,
                            const wire::Code& negative, uint8_t none, uint8_t got);

// "byte 1 must be 0x01 (read all settings), got 0x02" / "byte 1 must be the command code 1, got 2"
std::string fixed_byte_error(size_t index, const wire::Fixed& fixed, uint8_t got);
// "field 'ae_lock_on' must be 0x01 (on) or 0x02 (off), got 0x03"
std::string flag_error(const char* field, size_t index, const wire::Flag& flag, uint8_t got);

}  // namespace k40t::codec::detail
