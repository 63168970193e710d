// Camera command set 0x04, capture and storage (protocol document sections 3.4.1 to 3.4.10 and
// 3.4.33): work mode, photos, video, SD card, capabilities. The adapter (DJI Pilot) asks, the
// payload answers. A "set" command and the ACK of its "get" share one value struct (mixin).
#pragma once

#include <limits>

#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

enum class CameraWorkMode : uint8_t { kShootPhoto = 0, kRecordVideo = 1 };
const char* to_string(CameraWorkMode mode);

enum class ShootPhotoAction : uint8_t { kStop = 0, kStart = 1 };  // stop = end interval shooting
const char* to_string(ShootPhotoAction action);

enum class ShootPhotoType : uint8_t { kSingle = 1, kBurst = 4, kInterval = 6 };
const char* to_string(ShootPhotoType type);

enum class RecordAction : uint8_t { kStop = 0, kStart = 1 };
const char* to_string(RecordAction action);

constexpr uint8_t kIntervalShootUntilStopped = 255;

struct CameraWorkModeValue : ModeValue<CameraWorkMode, CameraWorkMode::kShootPhoto> {};

// 3.4.1 / 3.4.2: SetCameraWorkMode, CameraWorkModeAck, GetCameraWorkMode.
K40T_PSDK_SETTING(CameraWorkMode, camera_work_mode, CameraWorkModeValue, kCamera, 0x01, "3.4.1",
                  0x02, "3.4.2");

// 3.4.3: takes effect in shoot-photo mode only.
struct ShootPhoto : Command<CommandSet::kCamera, 0x03, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("shoot_photo", "3.4.3");
  K40T_PSDK_FIELDS((ShootPhotoAction, action, wire::u8, ShootPhotoAction::kStart));
};

// 3.4.4 byte 2.
K40T_PSDK_FLAGS(ShootPhotoState, shooting_single, shooting_interval, shooting_burst, storing);

// 3.4.4 ACK.
struct ShootPhotoStateValue {
  K40T_PSDK_FIELDS((ShootPhotoState, state, wire::packed8),
                   (uint16_t, interval_countdown_s, wire::u16));
};

// 3.4.4: GetShootPhotoState, ShootPhotoStateAck.
K40T_PSDK_GET(ShootPhotoState, shoot_photo_state, ShootPhotoStateValue, kCamera, 0x04, "3.4.4");

// 3.4.5 / 3.4.6: burst count applies to burst shooting, interval count and interval to interval
// shooting (count 1..254, or 255 = until stopped; interval 1..255 s; 0 is reserved for both).
// The interval is a uint8_t as the document gives it, or a uint16_t as DJI's headers give it
// (ShootPhotoModeWide, header_variants.h).
template <class Interval>
struct BasicShootPhotoMode {
  K40T_PSDK_FIELDS((ShootPhotoType, type, wire::u8, ShootPhotoType::kSingle),
                   (uint8_t, burst_count, wire::u8), (uint8_t, interval_count, wire::u8),
                   (Interval, interval_s, wire::Raw<Interval>{}));
  Status validate() const {
    // Counts and interval matter only for the type that uses them (0 is reserved there).
    if (type != ShootPhotoType::kInterval) return Status::ok();
    return first_failure(
        check_int("interval_count", interval_count, 1, 255),
        check_int("interval_s", interval_s, 1, std::numeric_limits<Interval>::max(), "s"));
  }
};
struct ShootPhotoMode : BasicShootPhotoMode<uint8_t> {};

// 3.4.5 / 3.4.6: SetShootPhotoMode, ShootPhotoModeAck, GetShootPhotoMode.
K40T_PSDK_SETTING(ShootPhotoMode, shoot_photo_mode, ShootPhotoMode, kCamera, 0x05, "3.4.5", 0x06,
                  "3.4.6");

// 3.4.7.
struct RecordVideo : Command<CommandSet::kCamera, 0x07, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("record_video", "3.4.7");
  K40T_PSDK_FIELDS((RecordAction, action, wire::u8, RecordAction::kStart));
};

// 3.4.8 ACK.
struct RecordStateValue {
  K40T_PSDK_FIELDS((bool, recording, wire::u8),
                   (uint16_t, duration_s, wire::u16));  // of the current recording
};

// 3.4.8: GetRecordState, RecordStateAck.
K40T_PSDK_GET(RecordState, record_state, RecordStateValue, kCamera, 0x08, "3.4.8");

// 3.4.9 bytes 2:3.
K40T_PSDK_FLAGS(SdCardState, inserted, initializing, read_only, formatted, formatting, full,
                verified, invalid_format, has_error);

// 3.4.9 ACK.
struct SdCardInfoValue {
  K40T_PSDK_FIELDS((SdCardState, state, wire::packed16), (uint32_t, capacity_mb, wire::u32),
                   (uint32_t, remaining_mb, wire::u32), (uint32_t, remaining_shots, wire::u32),
                   (uint32_t, remaining_record_time_s, wire::u32));
};

// 3.4.9: GetSdCardInfo, SdCardInfoAck.
K40T_PSDK_GET(SdCardInfo, sd_card_info, SdCardInfoValue, kCamera, 0x09, "3.4.9");

// 3.4.10 ACK: one reserved byte after the code.
struct FormatSdCardAck : Reply<CommandSet::kCamera, 0x0A, Sender::kPayload> {
  K40T_PSDK_NAMED("format_sd_card_ack", "3.4.10");
  K40T_PSDK_LAYOUT(s, v) { v("reserved", wire::gap, wire::Reserved{1}); }
};

// 3.4.10.
K40T_PSDK_NO_DATA(FormatSdCard, kCamera, 0x0A, FormatSdCardAck, "format_sd_card", "3.4.10");

// 3.4.33 byte 2.
K40T_PSDK_FLAGS(CameraCapability, camera_commands, optical_zoom, digital_zoom, focus, metering);

// 3.4.33 ACK.
struct CameraCapabilityValue {
  K40T_PSDK_FIELDS((CameraCapability, supported, wire::packed8));
};

// 3.4.33: GetCameraCapability, CameraCapabilityAck.
K40T_PSDK_GET(CameraCapability, camera_capability, CameraCapabilityValue, kCamera, 0xFF, "3.4.33");

}  // namespace k40t::psdk
