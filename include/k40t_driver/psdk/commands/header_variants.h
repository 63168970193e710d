// Where DJI's published PSDK 1.x headers (psdk_cmdset_*.h, V1.0.0) disagree with the protocol
// document, the payload's side is a parameter (`PsdkLayout`); docs/psdk.md P28..P32 give the
// evidence and the default. What the adapter sends is decoded by its length where the two
// readings differ in length, so either adapter is understood whatever the parameter says.
//   P28 3.5.1: gimbal state mode numbering (document: 1 following, 2 FPV; headers: one enum for
//       state and set, 1 FPV, 2 yaw follow, as 3.5.2 numbers the set);
//   P29 3.4.9: SD card state bits (document: 0 inserted, 1 initializing, 2 read-only, 3 formatted,
//       4 formatting, 5 full, 6 verified, 7 invalid format, 8 error; headers: 0 inserted,
//       1 verified, 2 initializing, 3 read-only, 4 formatting, 5 full, 6 invalid format, 7 error,
//       no "formatted");
//   P30 3.4.5/3.4.6: interval width (document: uint8; headers: uint16);
//   P31 3.3.1: link bandwidth push length (document: 42 bytes; DJI V1.0.0: 33, no OSDK fields).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/psdk/commands/camera_capture.h"
#include "k40t_driver/psdk/commands/data_push.h"
#include "k40t_driver/psdk/commands/declare.h"
#include "k40t_driver/psdk/commands/gimbal.h"

namespace k40t::psdk {

enum class PsdkLayout : uint8_t { kDjiHeaders = 0, kDocument = 1 };
const char* to_string(PsdkLayout layout);
// "dji_headers" or "document".
bool parse_psdk_layout(const std::string& text, PsdkLayout& out);

// P28: the state report's mode byte for `mode` (named as 3.5.2 names it).
uint8_t gimbal_state_mode_code(GimbalMode mode, PsdkLayout layout);

// P29: the 16-bit state word of `state` in `layout`'s bit positions, and back.
uint16_t sd_card_state_word(const SdCardState& state, PsdkLayout layout);
SdCardState sd_card_state_from_word(uint16_t word, PsdkLayout layout);
// The ACK whose encoding (SdCardInfoAck's document layout) carries `ack.state` in `layout`'s bit
// positions: what the payload sends.
SdCardInfoAck sd_card_ack_for(const SdCardInfoAck& ack, PsdkLayout layout);

// P30: shoot photo mode with a two-byte interval (headers).
struct ShootPhotoModeWide : BasicShootPhotoMode<uint16_t> {};
struct ShootPhotoModeWideAck : Reply<CommandSet::kCamera, 0x06, Sender::kPayload>,
                               ShootPhotoModeWide {
  K40T_PSDK_NAMED("get_shoot_photo_mode_ack_u16", "3.4.6");
};
// 3.4.5's DATA by its length: 4 bytes (document, uint8 interval) or 5 and more (headers,
// uint16 interval).
Result<ShootPhotoModeWide> decode_shoot_photo_mode(const uint8_t* data, size_t size);
// The get ACK's DATA in `layout`.
Result<Data> encode_shoot_photo_mode_ack(const ShootPhotoModeWide& mode, PsdkLayout layout);

// P31: 3.3.1 of 42 bytes, or of 33 (the OSDK fields absent: `has_osdk_fields` false, zeros).
Result<LinkBandwidthPush> decode_link_bandwidth(const uint8_t* data, size_t size,
                                                bool* has_osdk_fields);
constexpr size_t kLinkBandwidthShortSize = 33;

}  // namespace k40t::psdk
