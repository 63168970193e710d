// Every PSDK command struct (protocol document chapter 3).
#pragma once

#include "k40t_driver/psdk/commands/app_function.h"
#include "k40t_driver/psdk/commands/camera_capture.h"
#include "k40t_driver/psdk/commands/camera_lens.h"
#include "k40t_driver/psdk/commands/data_push.h"
#include "k40t_driver/psdk/commands/gimbal.h"
#include "k40t_driver/psdk/commands/osdk_function.h"
#include "k40t_driver/psdk/commands/payload_state.h"
#include "k40t_driver/psdk/commands/positioning.h"
#include "k40t_driver/psdk/commands/widgets.h"

namespace k40t::psdk {

template <class... T>
struct TypeList {};

// Every command of chapter 3, in document order (their ACK structs are reached through ::Ack).
using AllCommands = TypeList<
    // 0x01 payload state
    IdentityVerification, GetPsdkVersion, Handshake, GetProductInfo, GetSkyportVersion,
    GetProductAlias,
    // 0x02 APP function
    TransparentFromMobile, TransparentToMobile, FloatingWindowMessage, GetWidgetListLength,
    GetWidgetListData, GetWidgetGroupCount, GetWidgetGroupData, SetWidgetValue, GetTextInputBox,
    // 0x03 data push
    LinkBandwidthPush, AttitudePush, BatteryInfoPush, GpsPush, UavStatePush, AppDateTimePush,
    BarometricAltitudePush, RawGpsPush, RawRtkPush, UtcTimePush, OtherPayloadTypePush,
    OtherPayloadFocalLengthPush,
    // 0x04 camera
    SetCameraWorkMode, GetCameraWorkMode, ShootPhoto, GetShootPhotoState, SetShootPhotoMode,
    GetShootPhotoMode, RecordVideo, GetRecordState, GetSdCardInfo, FormatSdCard, SetMeteringMode,
    GetMeteringMode, SetSpotMeteringZone, GetSpotMeteringZone, SetFocusMode, GetFocusMode,
    SetFocusZone, GetFocusZone, SetDigitalZoomFactor, GetDigitalZoomFactor, GetOpticalZoomSpec,
    SetOpticalZoomFocalLength, GetOpticalZoomFocalLength, GetOpticalZoomFactor, StartContinuousZoom,
    StopContinuousZoom, SetFocusAssistant, GetFocusAssistant, GetFocusRingUpperBound, SetFocusRing,
    GetFocusRing, GetDigitalZoomSpec, GetCameraCapability,
    // 0x05 gimbal
    GetGimbalState, SetGimbalMode, GimbalReturnHead, ControlGimbalSpeed, ControlGimbalAngle,
    ControlGimbalJointAngle, CalibrateGimbal, GetCalibrationProgress, GetGimbalAdditionalStatus,
    GetGimbalCapability,
    // 0x06 OSDK function
    TransparentFromOnboard, TransparentToOnboard,
    // 0x07 positioning
    GetPosition>;

}  // namespace k40t::psdk
