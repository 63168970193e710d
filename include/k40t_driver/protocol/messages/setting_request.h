// The shape most camera setting requests share (sections 3.2.2 and 3.2.3): one value byte, after
// the 0x00 "start setting" byte in the visible-camera family, then reserved zeros
// (docs/protocol/decisions.md#a11; optional on receive). ACK: the response code only.
//
// A request of that shape derives from ByteSettingRequest<Self, prefix, reserved bytes> and
// declares, besides kId, kName and kSection, its one field and
//   static constexpr auto kValue = &Self::field;        // the field
//   static constexpr const char* kValueName = "field";  // its name in fields() and errors
// and, by the field's type:
//   integer: static constexpr int64_t kMin, kMax;       // the document's range
//   enum:    nothing (validated against the codes its to_string() knows)
//   bool:    static constexpr uint8_t kOnCode, kOffCode;
// Optionally static constexpr uint8_t kValueMask: the bits of the byte that carry the value (the
// others are reserved: sent as zero, ignored on receive).
// The result meets message.h's contract like a hand-written struct (kDirection, kSize,
// kMinSize, Ack, validate, encode, decode and fields come from the base).
#pragma once

#include <type_traits>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::protocol {

constexpr uint8_t kStartSettingByte = 0x00;  // byte 1 of every visible-camera setting request

namespace detail {
// A fixed command byte ("0x01 read all settings", "0x00 start setting"). Any other value is not
// a message the struct can represent: decoding fails, naming the byte and what it must be.
Status expect_command_byte(ByteReader& r, uint8_t expected, const char* meaning);
// A two-valued byte into a bool: `on_code` -> true, `off_code` -> false, anything else is an
// error naming the field (the simulator must be able to refuse such a request).
Status read_switch(ByteReader& r, const char* field, uint8_t on_code, uint8_t off_code, bool* on);
}  // namespace detail

// "0x01 read all settings, 1 reserved" (sections 3.2.2.1 and 3.2.3.1); the settings come back
// in the data ACK `AckT`. A request derives from ReadAllSettingsRequest<AckT> and declares kId,
// kName and kSection.
template <class AckT>
struct ReadAllSettingsRequest {
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;
  static constexpr uint8_t kReadAllSettings = 0x01;
  using Ack = AckT;

  Status validate() const { return Status::ok(); }
  void encode(ByteWriter& w, const CodecOptions&) const {
    w.u8(kReadAllSettings);
    w.zeros(1);
  }
  Status decode(ByteReader& r, const CodecOptions&) {
    return detail::expect_command_byte(r, kReadAllSettings, "read all settings");
  }
  template <class Self, class V>
  static void fields(Self&, V&&) {}
};

enum class SettingPrefix { kNone, kStartSetting };

template <class Derived, SettingPrefix Prefix, size_t Reserved>
struct ByteSettingRequest {
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kMinSize = Prefix == SettingPrefix::kStartSetting ? 2 : 1;
  static constexpr size_t kSize = kMinSize + Reserved;
  static constexpr uint8_t kValueMask = 0xFF;
  using Ack = PlainAck;

  Status validate() const {
    const auto& value = derived().*Derived::kValue;
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, bool>) {
      return Status::ok();
    } else if constexpr (std::is_enum_v<T>) {
      return check_enum(Derived::kValueName, value);
    } else {
      return check_range(Derived::kValueName, static_cast<int64_t>(value), Derived::kMin,
                         Derived::kMax);
    }
  }

  void encode(ByteWriter& w, const CodecOptions&) const {
    if constexpr (Prefix == SettingPrefix::kStartSetting) w.u8(kStartSettingByte);
    const auto& value = derived().*Derived::kValue;
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, bool>) {
      w.u8(value ? Derived::kOnCode : Derived::kOffCode);
    } else {
      w.u8(static_cast<uint8_t>(value));
    }
    w.zeros(Reserved);
  }

  Status decode(ByteReader& r, const CodecOptions&) {
    Status start = Status::ok();
    if constexpr (Prefix == SettingPrefix::kStartSetting) {
      start = detail::expect_command_byte(r, kStartSettingByte, "start setting");
    }
    auto& value = derived().*Derived::kValue;
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, bool>) {
      const Status read =
          detail::read_switch(r, Derived::kValueName, Derived::kOnCode, Derived::kOffCode, &value);
      return first_failure(start, read);
    } else {
      value = static_cast<T>(r.u8() & Derived::kValueMask);
      return start;
    }
  }

  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v(Derived::kValueName, self.*Derived::kValue);
  }

 private:
  const Derived& derived() const { return static_cast<const Derived&>(*this); }
  Derived& derived() { return static_cast<Derived&>(*this); }
};

}  // namespace k40t::protocol
