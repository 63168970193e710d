#include "k40t_driver/ros/settings_services.h"

#include <std_srvs/Trigger.h>

#include "k40t_driver/SetPalette.h"
#include "k40t_driver/SetPhotoMode.h"
#include "k40t_driver/ros/service_support.h"

namespace k40t::driver {

namespace {
constexpr const char* kNoPod = "replay mode: there is no pod to send to";
}  // namespace

SettingsServices::SettingsServices(ros::NodeHandle nh, SettingsSync* settings)
    : nh_(nh), settings_(settings) {
  advertise_service<k40t_driver::SetPalette>(
      nh_, servers_, "set_palette", [this](auto& req, auto& res) {
        fill(res, write("set_palette", [&](Config& c) { c.palette = req.palette; }));
      });
  advertise_service<k40t_driver::SetPhotoMode>(
      nh_, servers_, "set_photo_mode", [this](auto& req, auto& res) {
        fill(res, write("set_photo_mode", [&](Config& c) {
               c.photo_mode = req.mode;
               c.timelapse_interval = req.timelapse_interval_s;
               c.burst_count = req.burst_count;
             }));
      });
  advertise_service<std_srvs::Trigger>(nh_, servers_, "read_settings",
                                       [this](auto&, std_srvs::Trigger::Response& res) {
                                         if (!settings_) return fail(res, kNoPod);
                                         const SettingsState state = settings_->read_from_pod();
                                         res.success = state.read_ok;
                                         res.message = state.read_message;
                                       });
}

session::AckResult SettingsServices::write(const std::string& service,
                                           const std::function<void(Config&)>& edit) {
  if (!settings_) return session::AckResult::not_sent(kNoPod);
  // The settings table says which setting the service writes.
  const SettingBinding* binding = binding_for_service(service);
  if (!binding) return session::AckResult::not_sent("no setting is written by " + service);
  return settings_->write(binding->name, edit);
}

}  // namespace k40t::driver
