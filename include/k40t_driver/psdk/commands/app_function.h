// APP function command set 0x02 (protocol document section 3.2): transparent data between the
// mobile app (MSDK) and the payload, DJI Pilot floating-window messages, the text input box.
// The widget commands 0x04..0x08 are in widgets.h.
#pragma once

#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

constexpr size_t kMaxTransparentFromMobile = 32;
constexpr size_t kMaxTransparentToMobile = 128;
constexpr size_t kMaxFloatingWindowData = 128;  // text + its terminating NUL
constexpr size_t kTextInputNameSize = 32;

// 3.2.1: 1..32 bytes from the mobile app. No ACK.
K40T_PSDK_TRANSPARENT(TransparentFromMobile, kAppFunction, 0x01, kAdapter,
                      kMaxTransparentFromMobile, "transparent_from_mobile", "3.2.1");

// 3.2.2: 1..128 bytes to the mobile app. No ACK. Encrypted by the payload (docs/psdk.md#frames).
K40T_PSDK_TRANSPARENT(TransparentToMobile, kAppFunction, 0x02, kPayload, kMaxTransparentToMobile,
                      "transparent_to_mobile", "3.2.2");

// 3.2.3: a UTF-8 line for DJI Pilot's floating window; on the wire the text and a terminating
// NUL, 1..128 bytes in all. No ACK. Encrypted by the payload (docs/psdk.md#frames).
struct FloatingWindowMessage : Command<CommandSet::kAppFunction, 0x03, Sender::kPayload, NoAck> {
  K40T_PSDK_NAMED("floating_window_message", "3.2.3");
  static constexpr size_t kMinBodySize = 1;
  static constexpr size_t kMaxBodySize = kMaxFloatingWindowData;
  std::string text;  // at most 127 bytes, no NUL

  Status validate() const { return codec::check_text("text", text, kMaxFloatingWindowData - 1); }
  void encode(ByteWriter& w) const { w.text(text, text.size() + 1); }
  Status decode(ByteReader& r) {
    text = r.text(r.remaining());  // up to the first NUL
    return Status::ok();
  }
  void describe(FieldSink& sink) const { sink.text("text", text); }
};

// 3.2.9 ACK.
struct TextInputBoxValue {
  K40T_PSDK_FIELDS((bool, display, wire::u8),
                   (std::string, name, wire::Text{kTextInputNameSize}),  // at most 31 bytes + NUL
                   (std::string, description,
                    wire::Text{kTextInputNameSize}));  // at most 31 bytes + NUL
};

// 3.2.9: parameters of DJI Pilot's text input box. GetTextInputBox, TextInputBoxAck.
K40T_PSDK_GET(TextInputBox, text_input_box, TextInputBoxValue, kAppFunction, 0x09, "3.2.9");

}  // namespace k40t::psdk
