// Coded values of the common camera family (document sections 3.2.1.1, 3.2.1.4 and 3.2.4): one
// enum per code table, the enumerators' values are the wire codes. Every to_string() returns the
// document's meaning, or nullptr for a code the document does not define (check_enum and the
// field visitor rely on that).
#pragma once

#include <cstdint>

namespace k40t::protocol {

// 0x000003 byte 1, 0x000300 byte 1.
enum class CaptureMode : uint8_t { kPhoto = 0, kVideo = 1 };
const char* to_string(CaptureMode v);

// 0x000003 byte 2 as reported (docs/protocol/decisions.md#a6: the English calls it "encoding
// format"; it is the resolution). Note the request 0x00030A numbers the same resolutions from 1:
// StreamResolution.
enum class ReportedStreamResolution : uint8_t { k1080p30 = 0, k720p30 = 1 };
const char* to_string(ReportedStreamResolution v);

// 0x00030A byte 1. The document marks 720P30 "not supported"; validation refuses it.
enum class StreamResolution : uint8_t { k1080p30 = 1, k720p30 = 2 };
const char* to_string(StreamResolution v);

// 0x000003 byte 3, 0x00030B byte 1.
enum class VideoEncoding : uint8_t { kH264 = 0, kH265 = 1 };
const char* to_string(VideoEncoding v);

// 0x000003 byte 4 (stream mode) and 0x000318 byte 1 (image mode): what the one RTSP stream shows.
// The document gives 0x05 and 0x06 both as "visible light" without telling them apart.
enum class ImageMode : uint8_t {
  kInfrared = 0x00,
  kVisible = 0x05,
  kVisibleAlt = 0x06,
  kSplit = 0x07
};
const char* to_string(ImageMode v);

// 0x000003 byte 5, 0x000308 byte 1.
enum class StreamBitrate : uint8_t {
  k1Mbps = 1,
  k1_5Mbps = 2,
  k2Mbps = 3,
  k4Mbps = 4,
  k8Mbps = 5,
  k12Mbps = 6,
};
const char* to_string(StreamBitrate v);
// The rate in Mbit/s, 0 for an undefined code.
double bitrate_mbps(StreamBitrate v);

// 0x000003 byte 6, 0x000301 byte 1.
enum class PhotoMode : uint8_t { kSingle = 0, kBurst = 1, kTimeLapse = 2 };
const char* to_string(PhotoMode v);

// 0x000003 byte 9.
enum class SdCardState : uint8_t {
  kNormal = 0,
  kAbnormal = 1,
  kSlow = 2,
  kMissing = 3,
  kFull = 4,
  kFormatError = 5,
};
const char* to_string(SdCardState v);

// 0x000008 byte 1.
enum class CameraUpgradeState : uint8_t {
  kSucceeded = 0,
  kFailed = 1,
  kUpgrading = 2,
  kRepairing = 3
};
const char* to_string(CameraUpgradeState v);

// Which cameras take the photo: 0x000302 and 0x000307 byte 1, status frames 0x020302/0x020307.
enum class PhotoLensMode : uint8_t {
  kDefault = 0,  // infrared + visible, "all storage"
  kInfrared = 1,
  kVisible = 2,
  kInfraredAndVisible = 3,
};
const char* to_string(PhotoLensMode v);

// Which cameras record: 0x000303 byte 1, status frame 0x020303 byte 1.
enum class RecordLensMode : uint8_t {
  kDefault = 0,  // infrared + visible
  kInfrared = 1,
  kVisible = 2,
  kInfraredAndVisible = 3,
  kStreamCapture = 4,  // records the 1920x1080 output stream
};
const char* to_string(RecordLensMode v);

// 0x000302 byte 2.
enum class PhotoAction : uint8_t { kStart = 0, kStop = 1 };  // stop: burst mode only
const char* to_string(PhotoAction v);

// 0x000303 byte 2.
enum class RecordAction : uint8_t { kStart = 1, kStop = 2 };
const char* to_string(RecordAction v);

// 0x000306 byte 1.
enum class ZoomCommand : uint8_t {
  kZoomIn = 0,
  kZoomOut = 1,
  kStop = 2,
  kStepIn = 3,
  kStepOut = 4
};
const char* to_string(ZoomCommand v);

// 0x000307 byte 2: visible photo resolution of a precise re-shoot.
enum class ReshootResolution : uint8_t {
  k8000x6000 = 0x14,
  k4000x3000 = 0x15,
  k5160x3890 = 0x16,
  k5664x4248 = 0x17,
};
const char* to_string(ReshootResolution v);

// 0x000311 byte 1.
enum class IpMode : uint8_t { kStatic = 0, kDhcp = 1 };
const char* to_string(IpMode v);

// 0x000313 byte 1.
enum class FocusCommand : uint8_t {
  kAuto = 0,
  kFinePlus = 1,   // "manual fine-tuning focus +"
  kFineMinus = 2,  // "manual fine-tuning focus -"
  kFineStop = 3,
  kArea = 4,  // area auto focus: the only command that uses the area bytes
  kOneShot = 5,
  kAutoAfterZoomOn = 6,
  kAutoAfterZoomOff = 7,
};
const char* to_string(FocusCommand v);

// 0x000319 and 0x000324 byte 1: 0x01 on, 0x02 off.
enum class FeatureSwitch : uint8_t { kOn = 1, kOff = 2 };
const char* to_string(FeatureSwitch v);

// Status frame 0x020302 byte 2. Codes 1 and 5 both read "single shot in progress".
enum class PhotoState : uint8_t {
  kDone = 0,
  kSingleShot = 1,
  kBurst = 2,
  kTimeLapse = 3,
  kStopped = 4,
  kSingleShot5 = 5,
  kFailed = 6,
  kNoSdCard = 7,
  kSdFull = 8,
  kSdAbnormal = 9,
  kSdSlow = 10,
  kSdFormatError = 11,
};
const char* to_string(PhotoState v);

// Status frame 0x020307 byte 2: like PhotoState but codes 1/2 differ and 12 is added.
enum class ReshootState : uint8_t {
  kDone = 0,
  kBurst = 1,
  kContinuous = 2,
  kTimeLapse = 3,
  kStopped = 4,
  kSingleShot = 5,
  kFailed = 6,
  kNoSdCard = 7,
  kSdFull = 8,
  kSdAbnormal = 9,
  kSdSlow = 10,
  kSdFormatError = 11,
  kReshooting = 12,
};
const char* to_string(ReshootState v);

// Status frame 0x020303 byte 2.
enum class RecordState : uint8_t {
  kStopped = 0,
  kRecording = 1,
  kTimeLapseWaiting = 2,
  kTimeLapseRecording = 3,
  kNoSdCard = 4,
  kSdFull = 5,
  kSdAbnormal = 6,
  kSdSlow = 7,
  kSdFormatError = 8,
};
const char* to_string(RecordState v);

// Status frame 0x020304 byte 1.
enum class ZoomProgress : uint8_t { kDone = 0, kZooming = 1 };
const char* to_string(ZoomProgress v);

// Status frame 0x02030C byte 1.
enum class TfUpgradeState : uint8_t { kSucceeded = 0, kUpgrading = 1, kFailed = 2 };
const char* to_string(TfUpgradeState v);

// Status frame 0x02030D byte 1.
enum class SdFormatState : uint8_t { kDone = 0, kFormatting = 1, kFailed = 2, kUnavailable = 3 };
const char* to_string(SdFormatState v);

// 0x000320 byte 2; 3 and above count as a usable fix.
enum class GpsFixStatus : uint8_t {
  kNotConnected = 0,
  kNoFix = 1,
  kFix2d = 2,
  kFix3d = 3,
  kDgps = 4,
  kRtkFloat = 5,
  kRtkFixed = 6,
  kStatic = 7,
  kPpp = 8,
};
const char* to_string(GpsFixStatus v);

}  // namespace k40t::protocol
