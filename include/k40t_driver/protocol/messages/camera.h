// The common camera family (document sections 3.2.1.1, 3.2.1.4 and 3.2.4, camera 0x04/0x01):
// include this for all of it. The structs live in smaller headers by job:
//   camera_enums.h        the code tables (modes, states, ...) with to_string()
//   camera_reports.h      periodic reports 0x000003 (system status) and 0x000008 (upgrade)
//   camera_capture.h      requests 0x000300-0x000307: modes, photo, record, zoom, re-shoot
//   camera_imaging.h      requests 0x000308-0x00030B, 0x000313, 0x000314, 0x000318, 0x000319,
//                         0x000324: stream settings, focus, OSD, image mode, AI, tracking
//   camera_system.h       requests 0x00030C-0x00030F, 0x000311, 0x000312, 0x000316, 0x000317
//                         and the data ACKs 0x010312 (IP) and 0x010317 (version)
//   camera_status.h       status frames 0x020302-0x02030D
//   flight_controller.h   0x000310 (camera asks for GPS) and 0x000320 (target position), with
//                         their data ACKs
// docs/protocol/camera.md lists the document's ambiguities and what these structs decide.
#pragma once

#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/camera_enums.h"
#include "k40t_driver/protocol/messages/camera_imaging.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/camera_status.h"
#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/protocol/messages/flight_controller.h"

namespace k40t::protocol {

// Every message struct of the camera family, from the lists its headers end with.
using CameraMessages =
    JoinedMessages<CameraReportMessages, CameraCaptureMessages, CameraImagingMessages,
                   CameraSystemMessages, CameraStatusMessages, FlightControllerMessages>;

}  // namespace k40t::protocol
