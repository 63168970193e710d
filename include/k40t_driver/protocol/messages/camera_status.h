// Status frames of the common camera family (document section 3.2.4): 0x0203xx frames the
// camera 0x04/0x01 sends to the host while it carries out request 0x0003xx.
//
// Byte order: section 2.1 says the multi-byte parameters of every payload "except ACK" are low
// byte first, and it defines status frames (high id byte 0x02) as a kind of message of their own,
// apart from ACKs (0x01). So the uint16 fields here (burst count, recording time) are low byte
// first and do not follow CodecOptions::ack_byte_order. Trailing reserved bytes are optional on
// receive.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/camera_enums.h"

namespace k40t::protocol {

// 0x020302, section 3.2.4.3, after 0x000302 (not for single shots): lens mode, photo state 0..11,
// uint16 number of burst photos, 3 reserved.
struct PhotoStatus {
  K40T_POD_MESSAGE(0x020302, "photo_status", "3.2.4.3");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 7;
  static constexpr size_t kMinSize = 4;

  PhotoLensMode lens = PhotoLensMode::kDefault;
  PhotoState state = PhotoState::kDone;
  uint16_t burst_count = 0;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("lens", self.lens);
    v("state", self.state);
    v("burst_count", self.burst_count);
  }
};

// 0x020303, section 3.2.4.4, 1 Hz while recording: lens mode, record state 0..8, uint16
// recording time, 3 reserved. The document gives the time no unit; at a 1 Hz rate it is read as
// seconds.
struct RecordStatus {
  K40T_POD_MESSAGE(0x020303, "record_status", "3.2.4.4");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 7;
  static constexpr size_t kMinSize = 4;

  RecordLensMode lens = RecordLensMode::kDefault;
  RecordState state = RecordState::kStopped;
  uint16_t recording_time_s = 0;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("lens", self.lens);
    v("state", self.state);
    v("recording_time_s", self.recording_time_s);
  }
};

// 0x020304, section 3.2.4.5, after 0x000304: zooming (1) or done (0), 1 reserved.
struct ZoomStatus {
  K40T_POD_MESSAGE(0x020304, "zoom_status", "3.2.4.5");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;

  ZoomProgress progress = ZoomProgress::kDone;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("progress", self.progress);
  }
};

// 0x020307, section 3.2.4.7, after 0x000307: lens mode, state 0..12, 5 reserved.
struct PreciseReshootStatus {
  K40T_POD_MESSAGE(0x020307, "precise_reshoot_status", "3.2.4.7");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 7;
  static constexpr size_t kMinSize = 2;

  PhotoLensMode lens = PhotoLensMode::kDefault;
  ReshootState state = ReshootState::kDone;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("lens", self.lens);
    v("state", self.state);
  }
};

// 0x02030C, section 3.2.4.11, after 0x00030C: TF-card upgrade state, 1 reserved.
struct TfCardUpgradeStatus {
  K40T_POD_MESSAGE(0x02030C, "tf_card_upgrade_status", "3.2.4.11");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 2;
  static constexpr size_t kMinSize = 1;

  TfUpgradeState state = TfUpgradeState::kUpgrading;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("state", self.state);
  }
};

// 0x02030D, section 3.2.4.12, 5 Hz after 0x00030D: SD format state 0..3, 2 reserved. The pod
// also reports "failed" when a format is asked for during recording or shooting.
struct SdFormatStatus {
  K40T_POD_MESSAGE(0x02030D, "sd_format_status", "3.2.4.12");
  static constexpr Direction kDirection = Direction::kPodToHost;
  static constexpr size_t kSize = 3;
  static constexpr size_t kMinSize = 1;

  SdFormatState state = SdFormatState::kFormatting;

  Status validate() const;
  void encode(ByteWriter& w, const CodecOptions& o) const;
  Status decode(ByteReader& r, const CodecOptions& o);
  template <class Self, class V>
  static void fields(Self& self, V&& v) {
    v("state", self.state);
  }
};

// Every message struct of this part of the camera family: the catalogue, the catalogue tests and
// the fuzz target take their entries from this list (message_list.h).
using CameraStatusMessages = MessageList<PhotoStatus, RecordStatus, ZoomStatus,
                                         PreciseReshootStatus, TfCardUpgradeStatus, SdFormatStatus>;

}  // namespace k40t::protocol
