// Coded values of the common camera family (document sections 3.2.1.1, 3.2.1.4 and 3.2.4): one
// enum per code table, the enumerators' values are the wire codes. Every to_string() returns the
// document's meaning, or nullptr for a code the document does not define (check_enum and the
// field visitor rely on that).
#pragma once

#include "k40t_driver/protocol/code_enum.h"

namespace k40t::protocol {

// 0x000003 byte 1, 0x000300 byte 1.
K40T_CODE_ENUM(CaptureMode, kPhoto = 0, kVideo = 1);

// 0x000003 byte 2 as reported (docs/protocol/decisions.md#a6: the English calls it "encoding
// format"; it is the resolution). Note the request 0x00030A numbers the same resolutions from 1:
// StreamResolution.
K40T_CODE_ENUM(ReportedStreamResolution, k1080p30 = 0, k720p30 = 1);

// 0x00030A byte 1. The document marks 720P30 "not supported"; validation refuses it.
K40T_CODE_ENUM(StreamResolution, k1080p30 = 1, k720p30 = 2);

// 0x000003 byte 3, 0x00030B byte 1.
K40T_CODE_ENUM(VideoEncoding, kH264 = 0, kH265 = 1);

// 0x000003 byte 4 (stream mode) and 0x000318 byte 1 (image mode): what the one RTSP stream shows.
// The document gives 0x05 and 0x06 both as "visible light" without telling them apart.
K40T_CODE_ENUM(ImageMode, kInfrared = 0x00, kVisible = 0x05, kVisibleAlt = 0x06, kSplit = 0x07);

// 0x000003 byte 5, 0x000308 byte 1.
K40T_CODE_ENUM(StreamBitrate, k1Mbps = 1, k1_5Mbps = 2, k2Mbps = 3, k4Mbps = 4, k8Mbps = 5,
               k12Mbps = 6);
// The rate in Mbit/s, 0 for an undefined code.
double bitrate_mbps(StreamBitrate v);

// 0x000003 byte 6, 0x000301 byte 1.
K40T_CODE_ENUM(PhotoMode, kSingle = 0, kBurst = 1, kTimeLapse = 2);

// 0x000003 byte 9.
K40T_CODE_ENUM(SdCardState, kNormal = 0, kAbnormal = 1, kSlow = 2, kMissing = 3, kFull = 4,
               kFormatError = 5);

// 0x000008 byte 1.
K40T_CODE_ENUM(CameraUpgradeState, kSucceeded = 0, kFailed = 1, kUpgrading = 2, kRepairing = 3);

// Which cameras take the photo: 0x000302 and 0x000307 byte 1, status frames 0x020302/0x020307.
// The default is infrared + visible, "all storage".
K40T_CODE_ENUM(PhotoLensMode, kDefault = 0, kInfrared = 1, kVisible = 2, kInfraredAndVisible = 3);

// Which cameras record: 0x000303 byte 1, status frame 0x020303 byte 1. The default is infrared +
// visible; the stream capture records the 1920x1080 output stream.
K40T_CODE_ENUM(RecordLensMode, kDefault = 0, kInfrared = 1, kVisible = 2, kInfraredAndVisible = 3,
               kStreamCapture = 4);

// 0x000302 byte 2; stop: burst mode only.
K40T_CODE_ENUM(PhotoAction, kStart = 0, kStop = 1);

// 0x000303 byte 2.
K40T_CODE_ENUM(RecordAction, kStart = 1, kStop = 2);

// 0x000306 byte 1.
K40T_CODE_ENUM(ZoomCommand, kZoomIn = 0, kZoomOut = 1, kStop = 2, kStepIn = 3, kStepOut = 4);

// 0x000307 byte 2: visible photo resolution of a precise re-shoot.
K40T_CODE_ENUM(ReshootResolution, k8000x6000 = 0x14, k4000x3000 = 0x15, k5160x3890 = 0x16,
               k5664x4248 = 0x17);

// 0x000311 byte 1.
K40T_CODE_ENUM(IpMode, kStatic = 0, kDhcp = 1);

// 0x000313 byte 1: kFinePlus/kFineMinus are "manual fine-tuning focus +/-"; kArea (area auto
// focus) is the only command that uses the area bytes.
K40T_CODE_ENUM(FocusCommand, kAuto = 0, kFinePlus = 1, kFineMinus = 2, kFineStop = 3, kArea = 4,
               kOneShot = 5, kAutoAfterZoomOn = 6, kAutoAfterZoomOff = 7);

// 0x000319 and 0x000324 byte 1: 0x01 on, 0x02 off.
K40T_CODE_ENUM(FeatureSwitch, kOn = 1, kOff = 2);

// Status frame 0x020302 byte 2. Codes 1 and 5 both read "single shot in progress".
K40T_CODE_ENUM(PhotoState, kDone = 0, kSingleShot = 1, kBurst = 2, kTimeLapse = 3, kStopped = 4,
               kSingleShot5 = 5, kFailed = 6, kNoSdCard = 7, kSdFull = 8, kSdAbnormal = 9,
               kSdSlow = 10, kSdFormatError = 11);

// Status frame 0x020307 byte 2: like PhotoState but codes 1/2 differ and 12 is added.
K40T_CODE_ENUM(ReshootState, kDone = 0, kBurst = 1, kContinuous = 2, kTimeLapse = 3, kStopped = 4,
               kSingleShot = 5, kFailed = 6, kNoSdCard = 7, kSdFull = 8, kSdAbnormal = 9,
               kSdSlow = 10, kSdFormatError = 11, kReshooting = 12);

// Status frame 0x020303 byte 2.
K40T_CODE_ENUM(RecordState, kStopped = 0, kRecording = 1, kTimeLapseWaiting = 2,
               kTimeLapseRecording = 3, kNoSdCard = 4, kSdFull = 5, kSdAbnormal = 6, kSdSlow = 7,
               kSdFormatError = 8);

// Status frame 0x020304 byte 1.
K40T_CODE_ENUM(ZoomProgress, kDone = 0, kZooming = 1);

// Status frame 0x02030C byte 1.
K40T_CODE_ENUM(TfUpgradeState, kSucceeded = 0, kUpgrading = 1, kFailed = 2);

// Status frame 0x02030D byte 1.
K40T_CODE_ENUM(SdFormatState, kDone = 0, kFormatting = 1, kFailed = 2, kUnavailable = 3);

// 0x000320 byte 2; 3 and above count as a usable fix.
K40T_CODE_ENUM(GpsFixStatus, kNotConnected = 0, kNoFix = 1, kFix2d = 2, kFix3d = 3, kDgps = 4,
               kRtkFloat = 5, kRtkFixed = 6, kStatic = 7, kPpp = 8);

}  // namespace k40t::protocol
