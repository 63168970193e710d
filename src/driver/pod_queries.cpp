#include "k40t_driver/driver/pod_queries.h"

#include "k40t_driver/protocol/messages/camera_system.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::driver {

namespace {

std::string dotted(int major, int minor, int patch) {
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

void add_error(std::string& to, const std::string& what, const std::string& why) {
  if (!to.empty()) to += "; ";
  to += what + ": " + why;
}

// A typed read whose failure (NACK, timeout, undecodable) is appended to `error`.
template <class Req>
std::optional<typename Req::Ack> read(PodDriver& driver, const char* what, std::string& error) {
  Result<typename Req::Ack> ack = driver.request_typed(Req{});
  if (!ack) {
    add_error(error, what, ack.error());
    return std::nullopt;
  }
  return ack.value();
}

}  // namespace

std::string PodVersions::hardware_id() const {
  if (gimbal_hardware.empty() && camera.empty()) return "K40T (versions not read)";
  return "K40T gimbal hw " + (gimbal_hardware.empty() ? "?" : gimbal_hardware) + " sw " +
         (gimbal_software.empty() ? "?" : gimbal_software) + " camera " +
         (camera.empty() ? "?" : camera);
}

PodVersions read_versions(PodDriver& driver) {
  PodVersions v;
  std::string error;
  if (auto gimbal =
          read<protocol::GimbalVersionRequest>(driver, "gimbal version (0x000018)", error)) {
    v.gimbal_hardware =
        dotted(gimbal->hardware_major, gimbal->hardware_minor, gimbal->hardware_patch);
    v.gimbal_software =
        dotted(gimbal->software_major, gimbal->software_minor, gimbal->software_patch);
  }
  if (auto camera =
          read<protocol::CameraVersionRequest>(driver, "camera version (0x000317)", error)) {
    v.camera = dotted(camera->major, camera->minor, camera->patch);
  }
  v.ok = error.empty();
  v.message = v.ok ? "ok" : error;
  return v;
}

PodSettings read_settings(PodDriver& driver) {
  PodSettings s;
  s.thermal =
      read<protocol::ThermalReadSettingsRequest>(driver, "thermal settings (0x000100)", s.error);
  s.visible =
      read<protocol::VisibleReadSettingsRequest>(driver, "visible settings (0x000200)", s.error);
  return s;
}

}  // namespace k40t::driver
