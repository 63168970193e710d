// Byte cursors with ByteWriter's and ByteReader's interface but no bounds or failure test per
// byte, for a layout of fixed size that was checked once against the buffer (message_layout.h
// claims kSize bytes, then encodes or decodes every field through these). The layout visitors
// (layout.h) take either kind.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "k40t_driver/codec/byte_io.h"

namespace k40t::codec {

class UncheckedWriter {
 public:
  explicit UncheckedWriter(uint8_t* p) : p_(p) {}
  void u8(uint8_t v) { *p_++ = v; }
  void u16(uint16_t v, ByteOrder order) { put(v, 2, order); }
  void u32(uint32_t v, ByteOrder order = ByteOrder::kLittle) { put(v, 4, order); }
  void u64(uint64_t v, ByteOrder order = ByteOrder::kLittle) { put(v, 8, order); }
  void zeros(size_t n) {
    std::memset(p_, 0, n);
    p_ += n;
  }
  // Validation has checked the width; a longer text is cut rather than overrun the claim.
  void text(const std::string& s, size_t width) {
    const size_t n = std::min(s.size(), width);
    std::memcpy(p_, s.data(), n);
    std::memset(p_ + n, 0, width - n);
    p_ += width;
  }

 private:
  void put(uint64_t v, size_t n, ByteOrder order) {
    for (size_t i = 0; i < n; ++i) {
      p_[i] = static_cast<uint8_t>(v >> ((order == ByteOrder::kLittle ? i : n - 1 - i) * 8));
    }
    p_ += n;
  }
  uint8_t* p_;
};

class UncheckedReader {
 public:
  // `data` holds `size` bytes; `start` is their position in the payload (for "byte N" errors).
  UncheckedReader(const uint8_t* data, size_t size, size_t start)
      : begin_(data), p_(data), end_(data + size), start_(start) {}
  bool ok() const { return true; }
  size_t position() const { return start_ + static_cast<size_t>(p_ - begin_); }
  size_t remaining() const { return static_cast<size_t>(end_ - p_); }
  uint8_t u8() { return *p_++; }
  uint16_t u16(ByteOrder order) { return static_cast<uint16_t>(get(2, order)); }
  uint32_t u32(ByteOrder order = ByteOrder::kLittle) {
    return static_cast<uint32_t>(get(4, order));
  }
  uint64_t u64(ByteOrder order = ByteOrder::kLittle) { return get(8, order); }
  std::string text(size_t width) {
    size_t n = 0;
    while (n < width && p_[n] != 0) ++n;
    std::string s(reinterpret_cast<const char*>(p_), n);
    p_ += width;
    return s;
  }
  void skip(size_t n) { p_ += n; }

 private:
  uint64_t get(size_t n, ByteOrder order) {
    uint64_t v = 0;
    for (size_t i = 0; i < n; ++i) {
      v |= static_cast<uint64_t>(p_[i]) << ((order == ByteOrder::kLittle ? i : n - 1 - i) * 8);
    }
    p_ += n;
    return v;
  }
  const uint8_t* begin_;
  const uint8_t* p_;
  const uint8_t* end_;
  size_t start_;
};

}  // namespace k40t::codec
