// Bounds-checked little/big-endian reads and writes over byte buffers.
//
// Every multi-byte value is assembled byte by byte (no pointer casts, no alignment or aliasing
// assumptions). Both classes have a sticky failure flag: reading past the end or writing past the
// capacity returns zero / drops the bytes and marks the object failed, so a decoder can read all
// its fields and check ok() once at the end.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace k40t::codec {

enum class ByteOrder { kLittle, kBig };

class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  bool ok() const { return !failed_; }
  size_t position() const { return pos_; }
  size_t remaining() const { return failed_ ? 0 : size_ - pos_; }
  size_t size() const { return size_; }

  uint8_t u8() { return need(1) ? data_[pos_++] : 0; }
  int8_t i8() { return static_cast<int8_t>(u8()); }
  uint16_t u16(ByteOrder order = ByteOrder::kLittle) {
    return static_cast<uint16_t>(uint_n(2, order));
  }
  int16_t i16(ByteOrder order = ByteOrder::kLittle) { return static_cast<int16_t>(u16(order)); }
  uint32_t u32(ByteOrder order = ByteOrder::kLittle) {
    return static_cast<uint32_t>(uint_n(4, order));
  }
  int32_t i32(ByteOrder order = ByteOrder::kLittle) { return static_cast<int32_t>(u32(order)); }
  uint64_t u64(ByteOrder order = ByteOrder::kLittle) { return uint_n(8, order); }
  int64_t i64(ByteOrder order = ByteOrder::kLittle) { return static_cast<int64_t>(u64(order)); }

  // A fixed-width text field: `width` bytes, the string ends at the first NUL (if any).
  std::string text(size_t width) {
    if (!need(width)) return {};
    size_t n = 0;
    while (n < width && data_[pos_ + n] != 0) ++n;
    std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
    pos_ += width;
    return s;
  }

  void skip(size_t n) {
    if (need(n)) pos_ += n;
  }

  // The next `n` bytes, the reader moving past them; nullptr (and failed) when fewer remain. For
  // decoders of fixed size that then read without a check per byte.
  const uint8_t* claim(size_t n) {
    if (!need(n)) return nullptr;
    const uint8_t* p = data_ + pos_;
    pos_ += n;
    return p;
  }

 private:
  bool need(size_t n) {
    if (failed_ || size_ - pos_ < n) {
      failed_ = true;
      return false;
    }
    return true;
  }
  uint64_t uint_n(size_t n, ByteOrder order) {
    if (!need(n)) return 0;
    uint64_t v = 0;
    for (size_t i = 0; i < n; ++i) {
      const size_t shift = (order == ByteOrder::kLittle ? i : n - 1 - i) * 8;
      v |= static_cast<uint64_t>(data_[pos_ + i]) << shift;
    }
    pos_ += n;
    return v;
  }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  bool failed_ = false;
};

class ByteWriter {
 public:
  ByteWriter(uint8_t* data, size_t capacity) : data_(data), capacity_(capacity) {}

  bool ok() const { return !failed_; }
  size_t size() const { return pos_; }

  void u8(uint8_t v) {
    if (need(1)) data_[pos_++] = v;
  }
  void i8(int8_t v) { u8(static_cast<uint8_t>(v)); }
  void u16(uint16_t v, ByteOrder order = ByteOrder::kLittle) { uint_n(v, 2, order); }
  void i16(int16_t v, ByteOrder order = ByteOrder::kLittle) {
    u16(static_cast<uint16_t>(v), order);
  }
  void u32(uint32_t v, ByteOrder order = ByteOrder::kLittle) { uint_n(v, 4, order); }
  void i32(int32_t v, ByteOrder order = ByteOrder::kLittle) {
    u32(static_cast<uint32_t>(v), order);
  }
  void u64(uint64_t v, ByteOrder order = ByteOrder::kLittle) { uint_n(v, 8, order); }
  void i64(int64_t v, ByteOrder order = ByteOrder::kLittle) {
    u64(static_cast<uint64_t>(v), order);
  }

  // Fixed-width text: the string's bytes, then zeros up to `width` (no terminator when full).
  // A longer string is a failure (validation should have caught it first).
  void text(const std::string& s, size_t width) {
    if (s.size() > width) {
      failed_ = true;
      return;
    }
    for (size_t i = 0; i < width; ++i) u8(i < s.size() ? static_cast<uint8_t>(s[i]) : 0);
  }

  // `n` zero bytes: the reserved bytes every request carries (docs/protocol/decisions.md#a11).
  void zeros(size_t n) {
    for (size_t i = 0; i < n; ++i) u8(0);
  }

  // `n` bytes to fill in place, the writer moving past them; nullptr (and failed) when they do
  // not fit. For encoders of fixed size that then write without a check per byte.
  uint8_t* claim(size_t n) {
    if (!need(n)) return nullptr;
    uint8_t* p = data_ + pos_;
    pos_ += n;
    return p;
  }

 private:
  bool need(size_t n) {
    if (failed_ || capacity_ - pos_ < n) {
      failed_ = true;
      return false;
    }
    return true;
  }
  void uint_n(uint64_t v, size_t n, ByteOrder order) {
    if (!need(n)) return;
    for (size_t i = 0; i < n; ++i) {
      const size_t shift = (order == ByteOrder::kLittle ? i : n - 1 - i) * 8;
      data_[pos_ + i] = static_cast<uint8_t>(v >> shift);
    }
    pos_ += n;
  }

  uint8_t* data_;
  size_t capacity_;
  size_t pos_ = 0;
  bool failed_ = false;
};

}  // namespace k40t::codec
