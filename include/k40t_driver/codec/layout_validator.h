// The validating visitor of a declarative layout (layout.h explains layouts): validate() of a
// message is its layout() run with a LayoutValidator.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "k40t_driver/codec/layout_detail.h"
#include "k40t_driver/codec/result.h"
#include "k40t_driver/codec/value_checks.h"

namespace k40t::codec {

// The checks a layout implies, in wire order, keeping the first failure: the ranges it gives,
// enum codes the document defines, values a scaled integer or a float can carry, text that
// fits, bit fields that fit their width. With `options` (encoding), also what depends on them: a
// directed magnitude must fit its uint16 at the scale the options give.
// `Options`: the family's options type (the pod's CodecOptions), deduced from the pointer given.
template <class Options = wire::NoOptions>
class LayoutValidator {
 public:
  explicit LayoutValidator(Status& result, const Options* options = nullptr)
      : result_(result), options_(options) {}
  template <class T, class Int>
  void operator()(const char* name, const T& v, wire::Raw<Int> t) const {
    if constexpr (std::is_enum_v<T>) {
      if (!t.any_code) keep(check_enum(name, v));
    }
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
      if (t.limits.set) int_range(name, static_cast<int64_t>(v), t.limits);
    }
  }
  template <class Int>
  void operator()(const char* name, double v, wire::Scaled<Int> s) const {
    if (s.limits.set) {
      range(name, v, s.limits.lo, s.limits.hi, s.limits.unit);
    } else {
      range(name, v, std::numeric_limits<Int>::min() / s.scale,
            std::numeric_limits<Int>::max() / s.scale);
    }
  }
  template <class T, class Float>
  void operator()(const char* name, T v, wire::Real<Float> r) const {
    const double limit = static_cast<double>(std::numeric_limits<Float>::max()) / r.scale;
    range(name, static_cast<double>(v), -limit, limit);
  }
  // The value is only meaningful, and only checked, while switched on.
  template <class B, class D, class Int>
  void operator()(const char*, const wire::Switchable<B, D>& p, wire::OrOff<Int> t) const {
    if (*p.on) (*this)(p.value_name, static_cast<double>(*p.value), t.value);
  }
  // Checked whether or not it moves (the value of a "no movement" axis is sent as 0 anyway).
  template <class B, class D, class O>
  void operator()(const char*, const wire::Switchable<B, D>& p, const wire::Directed<O>& d) const {
    if (d.limits.set) {
      range(p.value_name, static_cast<double>(*p.value), d.limits.lo, d.limits.hi, d.limits.unit);
    }
    if constexpr (std::is_same_v<O, Options>) {
      if (options_ != nullptr && result_.is_ok()) {
        // A "no movement" axis sends 0 whatever its value.
        const double sent = *p.on ? static_cast<double>(*p.value) : 0.0;
        keep(detail::check_magnitude(p.value_name, sent, d.scale_name, d.limits,
                                     detail::option(options_, d.scale)));
      }
    }
  }
  template <class T, class Tag, class Rule>
  void operator()(const char* name, const T& v, const wire::Ruled<Tag, Rule>& r) const {
    if (result_.is_ok()) keep(r.rule(name, v));
  }
  // A terminated width includes the NUL: a full-width name would not be terminated, which the
  // PSDK document's "with \0 as the ending character" rules out.
  template <class T, class C>
  void operator()(const char* name, const T& v, wire::Custom<C>) const {
    keep(C::check(name, v));
  }
  void operator()(const char* name, const std::string& v, wire::Text t) const {
    keep(check_text(name, v, t.terminated ? t.width - 1 : t.width));
  }
  template <class Tag>
  void operator()(const char*, const wire::Gap&, Tag) const {}
  void operator()(const char*, const bool&, wire::Flag) const {}
  template <size_t N>
  void operator()(const char*, const std::array<uint8_t, N>&, wire::Bytes<N>) const {}
  template <class Sub, class Int>
  void operator()(const char*, const Sub& v, wire::Packed<Int>) const {
    Sub::layout(v, *this);
  }
  template <class Sub>
  void operator()(const char*, const Sub& v, wire::Nested) const {
    Sub::body(v, *this);
  }
  template <class T>
  void operator()(const char* name, const T& v, wire::Bits b) const {
    if constexpr (std::is_enum_v<T>) keep(check_enum(name, v));
    const uint64_t raw = detail::to_raw<uint64_t>(v);
    const auto most = static_cast<int64_t>(detail::bit_mask<uint64_t>(b.width));
    if (b.limits.set) int_range(name, static_cast<int64_t>(raw), b.limits);
    // A bool, or a range inside the width, cannot overflow it: no second check.
    if (std::is_same_v<T, bool> || (b.limits.set && b.limits.lo >= 0 && b.limits.hi <= most))
      return;
    range(name, static_cast<int64_t>(raw), int64_t{0}, most);
  }

 private:
  void keep(Status&& s) const {
    if (result_.is_ok() && !s.is_ok()) result_ = std::move(s);
  }
  // check_range's own test (lo <= value <= hi, NaN out of range), made here: a value in range
  // costs two comparisons instead of a call and a Status returned through memory, which for a
  // small layout was most of validate() (bench_codec, LaserRangeAck encode). check_range, out of
  // line, is called only to write the error.
  template <class V>
  void range(const char* name, V value, V lo, V hi, const char* unit = "") const {
    if (!(value >= lo && value <= hi)) out_of_range(name, value, lo, hi, unit);
  }
  // Out of line and cold, so that a validate() whose values are in range needs no stack frame for
  // the Status check_range returns.
  template <class V>
  [[gnu::noinline, gnu::cold]] void out_of_range(const char* name, V value, V lo, V hi,
                                                 const char* unit) const {
    keep(check_range(name, value, lo, hi, unit));
  }
  // A range given in a tag (doubles) for an integer field.
  void int_range(const char* name, int64_t value, const wire::Limits& limits) const {
    range(name, value, static_cast<int64_t>(limits.lo), static_cast<int64_t>(limits.hi),
          limits.unit);
  }
  Status& result_;
  const Options* options_;
};

}  // namespace k40t::codec
