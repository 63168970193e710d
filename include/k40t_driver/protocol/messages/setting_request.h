// The shape most camera setting requests share (sections 3.2.2 and 3.2.3): one value byte, after
// the 0x00 "start setting" byte in the visible-camera family, then reserved zeros
// (docs/protocol/decisions.md#a11; optional on receive). ACK: the response code only.
//
// A request of that shape derives from ByteSettingRequest<Self, prefix, reserved bytes> (or a
// family's alias of it) and declares, besides kId, kName and kSection, its one field:
//   K40T_SETTING_VALUE(uint8_t, sharpness, 0);  // the field, kValue = &Self::sharpness and
//                                               // kValueName = "sharpness" (fields(), errors)
// and, by the field's type:
//   integer: K40T_SETTING_RANGE(0, 100);         // kMin, kMax: the document's range
//   enum:    nothing (validated against the codes its to_string() knows)
//   bool:    K40T_SETTING_CODES(0x01, 0x02);     // kOnCode, kOffCode
// Optionally static constexpr uint8_t kValueMask: the bits of the byte that carry the value (the
// others are reserved: sent as zero, ignored on receive).
// The base turns these into the request's layout (codec/layout.h), which gives kDirection, kSize,
// kMinSize, Ack, validate, encode, decode and fields.
#pragma once

#include <type_traits>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/messages/ack.h"

// The value field of a one-value message (a setting request, or a status frame of one count or
// code: camera_status.h) and the two constants its base reads to encode it, after the field (a
// pointer to a member needs the member declared). `Self` is the message, from its base.
#define K40T_SETTING_VALUE(type, field, initial)    \
  type field = initial;                             \
  static constexpr const char* kValueName = #field; \
  static constexpr auto kValue = &Self::field
// The switch of a request with a switch and a value (visible.h's SwitchAndValueRequest): kOn and
// kOnName, like K40T_SETTING_VALUE's kValue and kValueName.
#define K40T_SETTING_SWITCH(field, initial)      \
  bool field = initial;                          \
  static constexpr const char* kOnName = #field; \
  static constexpr auto kOn = &Self::field
#define K40T_SETTING_RANGE(lo, hi)    \
  static constexpr int64_t kMin = lo; \
  static constexpr int64_t kMax = hi
#define K40T_SETTING_CODES(on, off)      \
  static constexpr uint8_t kOnCode = on; \
  static constexpr uint8_t kOffCode = off

namespace k40t::protocol {

constexpr uint8_t kStartSettingByte = 0x00;  // byte 1 of every visible-camera setting request

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

  K40T_LAYOUT(s, v) {
    v("command", wire::gap, wire::fixed(kReadAllSettings, "read all settings"));
    v("reserved", wire::gap, wire::reserved(1));
  }
};

// A byte holding a switch in bit 7 and a level 0..max in bits 6..0 (the settings ACKs 0x010100
// and 0x010200 pack denoise, enhancement, backlight and strong light this way); carried as
// wire::packed8.
template <class B, class L>
constexpr auto switch_and_level(const char* on_name, B& on, const char* level_name, L& level,
                                int max) {
  return wire::bit_group(wire::in_bits(on_name, on, wire::bit(7)),
                         wire::in_bits(level_name, level, wire::bits(0, 7).range(0, max)));
}

enum class SettingPrefix { kNone, kStartSetting };

template <class Derived, SettingPrefix Prefix, size_t Reserved>
struct ByteSettingRequest {
  using Self = Derived;
  static constexpr Direction kDirection = Direction::kHostToPod;
  static constexpr size_t kMinSize = Prefix == SettingPrefix::kStartSetting ? 2 : 1;
  static constexpr size_t kSize = kMinSize + Reserved;
  static constexpr uint8_t kValueMask = 0xFF;
  using Ack = PlainAck;

  // The one value byte's wire format, from the constants the request declares.
  K40T_LAYOUT(s, v) {
    using Self = std::conditional_t<std::is_const_v<S_>, const Derived, Derived>;
    auto& value = static_cast<Self&>(s).*Derived::kValue;
    using T = std::decay_t<decltype(value)>;
    if constexpr (Prefix == SettingPrefix::kStartSetting) {
      v("start", wire::gap, wire::fixed(kStartSettingByte, "start setting"));
    }
    if constexpr (std::is_same_v<T, bool>) {
      v(Derived::kValueName, value, wire::flag(Derived::kOnCode, Derived::kOffCode));
    } else if constexpr (std::is_enum_v<T>) {
      v(Derived::kValueName, value, wire::u8.mask(Derived::kValueMask));
    } else {
      v(Derived::kValueName, value,
        wire::u8.range(Derived::kMin, Derived::kMax).mask(Derived::kValueMask));
    }
    v("reserved", wire::gap, wire::reserved(Reserved));
  }
};

}  // namespace k40t::protocol
