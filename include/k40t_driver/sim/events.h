// Things the simulated pod reports when they happen (rather than at a fixed rate): the status
// frames of the document (0x0203xx, 0x020406 excepted: it is periodic), the upgrade/repair
// progress report 0x000008, and the pod's own GPS request before each photo (0x000310). The model
// appends them to an EventQueue as it steps; the front-end drains the queue and sends frames.
// State codes carry the document's numbers so the front-end can pass them through unchanged.
#pragma once

#include <cstdint>
#include <variant>
#include <vector>

namespace k40t::sim {

// 0x020304 (section 3.2.4.5).
struct ZoomStatusEvent {
  bool zooming = false;
};

// 0x020302 (3.2.4.3) and, with `precise`, 0x020307 (3.2.4.7).
enum class PhotoState : uint8_t {
  kTaken = 0,
  kSingleInProgress = 1,
  kBurstInProgress = 2,
  kTimeLapseInProgress = 3,
  kStopped = 4,
  kSingleShot = 5,
  kFailed = 6,
  kNoSdCard = 7,
  kSdFull = 8,
  kCardAbnormal = 9,
  kSlowCard = 10,
  kFormatError = 11,
  kPreciseReshooting = 12,
};
struct PhotoStatusEvent {
  uint8_t lens_mode = 0;  // 0 default, 1 IR, 2 visible, 3 IR + visible
  PhotoState state = PhotoState::kTaken;
  uint16_t count = 0;    // photos taken so far in this burst / time-lapse
  bool precise = false;  // a precise re-shoot (0x020307)
};

// 0x020303 (3.2.4.4), 1 Hz while recording.
enum class RecordState : uint8_t {
  kStopped = 0,
  kRecording = 1,
  kWaitingTimeLapse = 2,
  kTimeLapse = 3,
  kNoSdCard = 4,
  kSdFull = 5,
  kCardAbnormal = 6,
  kSlowCard = 7,
  kFormatError = 8,
};
struct RecordStatusEvent {
  uint8_t lens_mode = 0;  // 0..4
  RecordState state = RecordState::kStopped;
  uint16_t seconds = 0;
};

// 0x02030D (3.2.4.12), 5 Hz while formatting.
enum class FormatState : uint8_t { kDone = 0, kInProgress = 1, kFailed = 2, kUnavailable = 3 };
struct FormatStatusEvent {
  FormatState state = FormatState::kDone;
};

// 0x02030C (3.2.4.11).
enum class TfUpgradeState : uint8_t { kSucceeded = 0, kUpgrading = 1, kFailed = 2 };
struct TfUpgradeStatusEvent {
  TfUpgradeState state = TfUpgradeState::kSucceeded;
};

// 0x000008 (3.2.1.4), 1 Hz while upgrading or repairing (the simulator reports gimbal
// calibrations as repairs), and once more when done.
enum class MaintenanceState : uint8_t {
  kSucceeded = 0,
  kFailed = 1,
  kUpgrading = 2,
  kRepairing = 3
};
struct MaintenanceEvent {
  MaintenanceState state = MaintenanceState::kSucceeded;
  uint8_t progress = 0;  // 0..100
  // A gimbal calibration's: sent only by a pod whose calibration_end is "status"
  // (docs/protocol/decisions.md#conventions).
  bool calibration = false;
};

// The pod asks the flight controller for GPS at this time of day (0x000310, 3.2.4.15) just
// before a photo; the answer is attached to photo `photo_id`.
struct TimeOfDay {
  uint8_t hour = 0;
  uint8_t minute = 0;
  uint8_t second = 0;
  uint16_t millisecond = 0;
};
struct GpsRequestEvent {
  uint64_t photo_id = 0;
  TimeOfDay time;
};

using PodEvent =
    std::variant<ZoomStatusEvent, PhotoStatusEvent, RecordStatusEvent, FormatStatusEvent,
                 TfUpgradeStatusEvent, MaintenanceEvent, GpsRequestEvent>;
using EventQueue = std::vector<PodEvent>;

}  // namespace k40t::sim
