#include "k40t_driver/protocol/messages/camera.h"

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {

// Requests whose ACK is the bare response code get their "<name>_ack" entry from the catalogue.
void add_camera_messages(std::vector<MessageInfo>& out) {
  out.insert(out.end(), {
                            // periodic reports
                            info_of<CameraSystemStatus>(),
                            info_of<CameraUpgradeStatus>(),
                            // requests host -> camera
                            info_of<CaptureModeRequest>(),
                            info_of<PhotoSettingsRequest>(),
                            info_of<TakePhotoRequest>(),
                            info_of<RecordRequest>(),
                            info_of<ZoomRatioRequest>(),
                            info_of<ContinuousZoomRequest>(),
                            info_of<PreciseReshootRequest>(),
                            info_of<StreamBitrateRequest>(),
                            info_of<StreamResolutionRequest>(),
                            info_of<StreamEncodingRequest>(),
                            info_of<TfCardUpgradeRequest>(),
                            info_of<FormatSdRequest>(),
                            info_of<TimeSyncRequest>(),
                            info_of<FactoryResetRequest>(),
                            info_of<SetIpRequest>(),
                            info_of<GetIpRequest>(),
                            info_of<FocusRequest>(),
                            info_of<OsdWatermarkRequest>(),
                            info_of<ShutdownRequest>(),
                            info_of<CameraVersionRequest>(),
                            info_of<ImageModeRequest>(),
                            info_of<AiRecognitionRequest>(),
                            info_of<BoxTrackingRequest>(),
                            // the flight controller's part, played by the host
                            info_of<CameraGpsRequest>(),
                            info_of<TargetGpsRequest>(),
                            // ACKs that carry data
                            info_of<GetIpAck>(),
                            info_of<CameraVersionAck>(),
                            info_of<CameraGpsAck>(),
                            info_of<TargetGpsAck>(),
                            // status frames
                            info_of<PhotoStatus>(),
                            info_of<RecordStatus>(),
                            info_of<ZoomStatus>(),
                            info_of<PreciseReshootStatus>(),
                            info_of<TfCardUpgradeStatus>(),
                            info_of<SdFormatStatus>(),
                        });
}

}  // namespace k40t::protocol
