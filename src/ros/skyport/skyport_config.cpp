#include "k40t_driver/ros/skyport/skyport_config.h"

#include "k40t_driver/psdk/app_key_file.h"
#include "k40t_driver/ros/param_reader.h"
#include "k40t_driver/skyport/version_text.h"

namespace k40t::driver::skyport {

namespace {
void read_layout(ParamReader& p, const std::string& name, psdk::PsdkLayout& out) {
  const std::string text = p.get<std::string>(name, psdk::to_string(out));
  if (!psdk::parse_psdk_layout(text, out))
    p.fail(name, "must be dji_headers or document, got '" + text + "'");
}

void read_version(ParamReader& p, const std::string& name, psdk::Version& out) {
  const std::string text = p.get<std::string>(name, "");
  if (!text.empty() && !parse_version(text, out))
    p.fail(name, "must be a version A.B.C.D (each 0..255), got '" + text + "'");
}
}  // namespace

Result<SkyportConfig> read_skyport_config(const ros::NodeHandle& nh) {
  SkyportConfig c;
  ParamReader p(nh);
  c.device = p.get<std::string>("device", "");
  if (p.error().empty() && c.device.empty())
    return Status::fail("parameter ~device (the SKYPORT UART URL) is required");
  c.baud = static_cast<int>(p.number("baud", c.baud, 1200, 4000000));
  c.credentials.app_name = p.get<std::string>("app_name", "");
  c.credentials.app_id = p.get<std::string>("app_id", "");
  c.credentials.developer_account = p.get<std::string>("developer_account", "");
  const std::string key_file = p.get<std::string>("app_key_file", "");
  if (!key_file.empty()) {
    Result<std::string> key = psdk::read_app_key_file(key_file);
    if (!key) return Status::fail("parameter ~app_key_file: " + key.error());
    c.credentials.app_key = key.value();
  } else {
    c.credentials.app_key = p.get<std::string>("app_key", "");
  }
  if (p.error().empty() && c.credentials.app_key.empty())
    return Status::fail("no app key: set ~app_key_file (preferred) or ~app_key");
  c.encryption = p.get("encryption", c.encryption);
  c.bridge.app_key = c.credentials.app_key;
  c.bridge.developer_account = c.credentials.developer_account;
  // DJI's code sends the app name and the app id as product name and id (docs/psdk.md P32).
  c.bridge.product_name =
      p.get("product_name",
            c.credentials.app_name.empty() ? c.bridge.product_name : c.credentials.app_name);
  c.bridge.alias = p.get("alias", c.bridge.alias);
  c.bridge.product_id = p.get(
      "product_id", c.credentials.app_id.empty() ? c.bridge.product_id : c.credentials.app_id);
  // 3.1.4: 32- and 16-byte text fields ending with NUL (docs/psdk.md P3).
  if (c.bridge.product_name.size() > 31)
    p.fail("product_name",
           "at most 31 bytes (3.1.4), got " + std::to_string(c.bridge.product_name.size()));
  if (c.bridge.product_id.size() > 15)
    p.fail("product_id",
           "at most 15 bytes (3.1.4), got " + std::to_string(c.bridge.product_id.size()));
  read_version(p, "firmware_version", c.bridge.firmware);
  read_layout(p, "gimbal_mode_layout", c.bridge.gimbal_mode_layout);
  read_layout(p, "sd_card_layout", c.bridge.sd_card_layout);
  read_layout(p, "interval_layout", c.bridge.interval_layout);
  read_layout(p, "gimbal_angle_layout", c.bridge.gimbal_angle_layout);
  read_version(p, "skyport_version", c.bridge.skyport_version);
  c.bridge.max_queued_jobs =
      static_cast<size_t>(p.number("max_queued_jobs", double(c.bridge.max_queued_jobs), 1, 1000));
  c.bridge.calibration_report_timeout_s =
      p.number("calibration_report_timeout", c.bridge.calibration_report_timeout_s, 0.1, 3600);
  c.bridge.tele_focal_length_mm =
      p.number("tele_focal_length_mm", c.bridge.tele_focal_length_mm, 0.1, 1000);
  c.bridge.max_optical_zoom = p.number("max_optical_zoom", c.bridge.max_optical_zoom, 1, 1000);
  c.bridge.max_hybrid_zoom = p.number("max_hybrid_zoom", c.bridge.max_hybrid_zoom, 1, 10000);
  c.bridge.photo_storing_s = p.number("photo_storing_time", c.bridge.photo_storing_s, 0, 60);
  c.feed_pod = p.get("feed_pod", c.feed_pod);
  c.feed_fix = p.get("feed_fix", c.feed_fix);
  if (c.feed_fix != "raw_gps" && c.feed_fix != "rtk")
    p.fail("feed_fix", "must be raw_gps or rtk, got '" + c.feed_fix + "'");
  c.world_frame = p.get("world_frame", c.world_frame);
  c.base_frame = p.get("base_frame", c.base_frame);
  c.reconfigure = p.get("pod_reconfigure", c.reconfigure);
  c.service_timeout_s = p.number("service_timeout", c.service_timeout_s, 0.01, 60);
  c.ack_timeout_s = p.number("ack_timeout", c.ack_timeout_s, 0.01, 60);
  c.silence_timeout_s = p.number("silence_timeout", c.silence_timeout_s, 0.01, 60);
  c.diagnostic_period_s = p.number("diagnostic_period", c.diagnostic_period_s, 0.01, 60);
  c.pps_topic = p.get("pps_topic", c.pps_topic);
  c.pod_stale_s = p.number("pod_stale_timeout", c.pod_stale_s, 0.1, 3600);
  c.position_min_interval_s = p.number("position_min_interval", c.position_min_interval_s, 0, 60);
  if (!p.error().empty()) return Status::fail(p.error());
  return c;
}

}  // namespace k40t::driver::skyport
