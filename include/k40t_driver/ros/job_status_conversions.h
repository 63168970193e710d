// The status frames of the pod's long operations (document section 3.2.4) as ROS messages: zoom
// (0x020304), precise re-shoot (0x020307), TF-card upgrade (0x02030C and the 0x000008 report)
// and SD format (0x02030D).
// Each carries the raw state code and the document's text for it.
#pragma once

#include <ros/time.h>

#include "k40t_driver/CameraUpgradeStatus.h"
#include "k40t_driver/PreciseReshootStatus.h"
#include "k40t_driver/SdFormatStatus.h"
#include "k40t_driver/TfCardUpgradeStatus.h"
#include "k40t_driver/ZoomStatus.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/camera_status.h"

namespace k40t::driver {

k40t_driver::ZoomStatus to_msg(const protocol::ZoomStatus& status, const ros::Time& stamp);
k40t_driver::PreciseReshootStatus to_msg(const protocol::PreciseReshootStatus& status,
                                         const ros::Time& stamp);
k40t_driver::TfCardUpgradeStatus to_msg(const protocol::TfCardUpgradeStatus& status,
                                        const ros::Time& stamp);
k40t_driver::SdFormatStatus to_msg(const protocol::SdFormatStatus& status, const ros::Time& stamp);
// The 1 Hz upgrade/repair report (0x000008) that goes with a TF-card upgrade.
k40t_driver::CameraUpgradeStatus to_msg(const protocol::CameraUpgradeStatus& status,
                                        const ros::Time& stamp);

}  // namespace k40t::driver
