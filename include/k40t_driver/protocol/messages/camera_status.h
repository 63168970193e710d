// Status frames of the common camera family (document section 3.2.4): 0x0203xx frames the
// camera 0x04/0x01 sends to the host while it carries out request 0x0003xx.
//
// Byte order: section 2.1 says the multi-byte parameters of every payload "except ACK" are low
// byte first, and it defines status frames (high id byte 0x02) as a kind of message of their own,
// apart from ACKs (0x01). So the uint16 fields here (burst count, recording time) are low byte
// first and do not follow CodecOptions::ack_byte_order. Trailing reserved bytes are optional on
// receive.
#pragma once

#include <type_traits>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_layout.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/camera_enums.h"
#include "k40t_driver/protocol/messages/setting_request.h"

namespace k40t::protocol {

// What the photo, record and re-shoot frames (0x020302, 0x020303, 0x020307) start with: the lens
// mode and the state of the operation.
template <class Lens, class State>
struct LensAndState {
  Lens lens = Lens::kDefault;
  State state{};  // code 0: done (photo, re-shoot), stopped (record)

  template <class S, class V>
  static void body(S& s, V&& v) {
    v("lens", s.lens, wire::u8);
    v("state", s.state, wire::u8);
  }
};

// 0x020302 and 0x020303: lens mode, state, a uint16 count, 3 reserved. The frame declares its
// count with K40T_SETTING_VALUE (setting_request.h).
template <class Derived, class Lens, class State>
struct CountedStatus : LensAndState<Lens, State> {
  using Self = Derived;  // for K40T_SETTING_VALUE
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 7;
  static constexpr size_t kMinSize = 4;

  K40T_LAYOUT(s, v) {
    using Self = std::conditional_t<std::is_const_v<S_>, const Derived, Derived>;
    LensAndState<Lens, State>::body(s, v);
    v(Derived::kValueName, static_cast<Self&>(s).*Derived::kValue, wire::u16);
    v("reserved", wire::gap, wire::reserved(3));
  }
};

// 0x020302, section 3.2.4.3, after 0x000302 (not for single shots): lens mode, photo state 0..11,
// uint16 number of burst photos, 3 reserved.
struct PhotoStatus : CountedStatus<PhotoStatus, PhotoLensMode, PhotoState> {
  K40T_POD_MESSAGE(0x020302, "photo_status", "3.2.4.3");
  K40T_SETTING_VALUE(uint16_t, burst_count, 0);
};

// 0x020303, section 3.2.4.4, 1 Hz while recording: lens mode, record state 0..8, uint16
// recording time, 3 reserved. The document gives the time no unit; at a 1 Hz rate it is read as
// seconds.
struct RecordStatus : CountedStatus<RecordStatus, RecordLensMode, RecordState> {
  K40T_POD_MESSAGE(0x020303, "record_status", "3.2.4.4");
  K40T_SETTING_VALUE(uint16_t, recording_time_s, 0);
};

// A frame that is one code and `Reserved` reserved bytes: 0x020304, 0x02030C, 0x02030D. The frame
// declares its code with K40T_SETTING_VALUE (setting_request.h).
template <class Derived, size_t Reserved>
struct CodeStatus {
  using Self = Derived;  // for K40T_SETTING_VALUE
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 1 + Reserved;
  static constexpr size_t kMinSize = 1;

  K40T_LAYOUT(s, v) {
    using Self = std::conditional_t<std::is_const_v<S_>, const Derived, Derived>;
    v(Derived::kValueName, static_cast<Self&>(s).*Derived::kValue, wire::u8);
    v("reserved", wire::gap, wire::reserved(Reserved));
  }
};

// 0x020304, section 3.2.4.5, after 0x000304: zooming (1) or done (0), 1 reserved.
struct ZoomStatus : CodeStatus<ZoomStatus, 1> {
  K40T_POD_MESSAGE(0x020304, "zoom_status", "3.2.4.5");
  K40T_SETTING_VALUE(ZoomProgress, progress, ZoomProgress::kDone);
};

// 0x020307, section 3.2.4.7, after 0x000307: lens mode, state 0..12, 5 reserved.
struct PreciseReshootStatus : LensAndState<PhotoLensMode, ReshootState> {
  K40T_POD_REPORT(0x020307, "precise_reshoot_status", "3.2.4.7", 7, 2);
  K40T_LAYOUT(s, v) {
    body(s, v);
    v("reserved", wire::gap, wire::reserved(5));
  }
};

// 0x02030C, section 3.2.4.11, after 0x00030C: TF-card upgrade state, 1 reserved.
struct TfCardUpgradeStatus : CodeStatus<TfCardUpgradeStatus, 1> {
  K40T_POD_MESSAGE(0x02030C, "tf_card_upgrade_status", "3.2.4.11");
  K40T_SETTING_VALUE(TfUpgradeState, state, TfUpgradeState::kUpgrading);
};

// 0x02030D, section 3.2.4.12, 5 Hz after 0x00030D: SD format state 0..3, 2 reserved. The pod
// also reports "failed" when a format is asked for during recording or shooting.
struct SdFormatStatus : CodeStatus<SdFormatStatus, 2> {
  K40T_POD_MESSAGE(0x02030D, "sd_format_status", "3.2.4.12");
  K40T_SETTING_VALUE(SdFormatState, state, SdFormatState::kFormatting);
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using CameraStatusMessages = MessageList<PhotoStatus, RecordStatus, ZoomStatus,
                                         PreciseReshootStatus, TfCardUpgradeStatus, SdFormatStatus>;

}  // namespace k40t::protocol
