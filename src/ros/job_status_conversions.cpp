#include "k40t_driver/ros/job_status_conversions.h"

#include "k40t_driver/driver/code_text.h"

namespace k40t::driver {

namespace {
// Every one of these messages is a header plus a state code and its text.
template <class RosMsg, class E>
RosMsg with_state(E state, const ros::Time& stamp) {
  RosMsg m;
  m.header.stamp = stamp;
  m.state = code_of(state);
  m.state_text = text_of(state);
  return m;
}
}  // namespace

k40t_driver::ZoomStatus to_msg(const protocol::ZoomStatus& status, const ros::Time& stamp) {
  return with_state<k40t_driver::ZoomStatus>(status.progress, stamp);
}

k40t_driver::PreciseReshootStatus to_msg(const protocol::PreciseReshootStatus& status,
                                         const ros::Time& stamp) {
  auto m = with_state<k40t_driver::PreciseReshootStatus>(status.state, stamp);
  m.lens = code_of(status.lens);
  return m;
}

k40t_driver::TfCardUpgradeStatus to_msg(const protocol::TfCardUpgradeStatus& status,
                                        const ros::Time& stamp) {
  return with_state<k40t_driver::TfCardUpgradeStatus>(status.state, stamp);
}

k40t_driver::SdFormatStatus to_msg(const protocol::SdFormatStatus& status, const ros::Time& stamp) {
  return with_state<k40t_driver::SdFormatStatus>(status.state, stamp);
}

k40t_driver::CameraUpgradeStatus to_msg(const protocol::CameraUpgradeStatus& status,
                                        const ros::Time& stamp) {
  auto m = with_state<k40t_driver::CameraUpgradeStatus>(status.state, stamp);
  m.progress_percent = status.progress_percent;
  return m;
}

}  // namespace k40t::driver
