#include "k40t_driver/ros/skyport/skyport_config.h"

#include "k40t_driver/psdk/app_key_file.h"
#include "k40t_driver/ros/param_reader.h"

namespace k40t::driver::skyport {

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
  c.bridge.product_name = p.get("product_name", c.bridge.product_name);
  c.bridge.alias = p.get("alias", c.bridge.alias);
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
  if (!p.error().empty()) return Status::fail(p.error());
  return c;
}

}  // namespace k40t::driver::skyport
