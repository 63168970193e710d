#include "k40t_driver/ros/ros_params.h"

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "k40t_driver/protocol/conventions.h"
#include "k40t_driver/ros/param_reader.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::driver {

Result<RosPodConfig> read_params(const ros::NodeHandle& private_nh) {
  ParamReader reader(private_nh);
  return read_params(reader);
}

namespace {

// The document's open readings (docs/protocol/decisions.md#conventions) besides the ones read
// above, each a text parameter (e.g. from k40t.launch conventions:=FILE.yaml, as `k40t probe`
// writes it); `from_parameters` gets the name of every reading that is set, for the
// `conventions` diagnostic.
void read_conventions(ParamReader& p, session::SessionOptions& s,
                      std::set<std::string>& from_parameters) {
  static const std::set<std::string> kReadAbove = {
      "crc_coverage",     "ack_byte_order",   "laser_status_byte_order",
      "gimbal_system_id", "camera_system_id", "angle_command_scale"};
  for (const protocol::ConventionInfo& info : protocol::convention_table()) {
    if (!p.has(info.name)) continue;
    from_parameters.insert(info.name);
    if (kReadAbove.count(info.name)) continue;
    const std::string value = p.get<std::string>(info.name, info.default_value);
    const Status set = info.set(info, {s.crc_coverage, s.codec}, value);
    // The message starts with the reading's name, which fail() already gives.
    if (!set) p.fail(info.name, set.message().substr(std::string(info.name).size() + 1));
  }
}

}  // namespace

Result<RosPodConfig> read_params(ParamReader& p) {
  RosPodConfig c;
  DriverOptions& d = c.driver;
  d.device = p.get<std::string>("device", "serial:///dev/ttyUSB0");
  d.baud = static_cast<int>(p.number("baud", 115200, 1200, 4000000));
  d.replay = p.get("replay", false);
  d.reconnect_max_delay_s = p.number("reconnect_max_delay", 1.0, 0.05, 60);
  // Checked here, with the others: a bad URL is a bad parameter, reported as one.
  if (!d.replay) {
    const auto link = transport::make_transport(device_url_with_baud(d.device, d.baud));
    if (!link) p.fail("device", "is wrong: " + link.error());
  }

  session::SessionOptions& s = d.session;
  const std::string coverage = p.get<std::string>("crc_coverage", "auto");
  if (Result<protocol::CrcCoverage> parsed = protocol::parse_crc_coverage(coverage)) {
    s.crc_coverage = parsed.value();
  } else {
    p.fail("crc_coverage", "must be auto, header_excluded or whole_frame, got '" + coverage + "'");
  }
  const std::string order = p.get<std::string>("ack_byte_order", "big");
  if (!protocol::parse_ack_byte_order(order, s.codec))
    p.fail("ack_byte_order", "must be big, little or auto, got '" + order + "'");
  const std::string laser_order = p.get<std::string>("laser_status_byte_order", "little");
  if (Result<protocol::ByteOrder> parsed = protocol::parse_byte_order(laser_order)) {
    s.codec.laser_status_byte_order = parsed.value();
  } else {
    p.fail("laser_status_byte_order", "must be little or big, got '" + laser_order + "'");
  }
  s.codec.gimbal_address.system = static_cast<uint8_t>(p.number("gimbal_system_id", 3, 0, 255));
  s.codec.camera_address.system = static_cast<uint8_t>(p.number("camera_system_id", 4, 0, 255));
  const double scale = p.number("angle_command_scale", 100, 1, protocol::kMaxAngleCommandScale);
  if (scale != std::floor(scale)) p.fail("angle_command_scale", "must be a whole number");
  s.codec.angle_command_scale = static_cast<int>(scale);
  read_conventions(p, s, d.conventions_from_parameters);
  s.ack_timeout = std::chrono::milliseconds(
      static_cast<int64_t>(1000 * p.number("ack_timeout", 0.3, 0.01, 10)));
  s.retries = static_cast<int>(p.number("retries", 2, 0, 10));

  d.time_sync_period_s = p.number("time_sync_period", 10.0, 0, 3600);
  d.time_zone_minutes_west = static_cast<int>(p.number("time_zone_minutes_west", 0, -840, 720));
  d.cmd_rate_timeout_s = p.number("cmd_rate_timeout", 0.5, 0.05, 10);
  const std::string gps = p.get<std::string>("gps_provider", "topics");
  if (gps != "topics" && gps != "none")
    p.fail("gps_provider", "must be topics or none, got '" + gps + "'");
  d.answer_gps_requests = gps == "topics";
  d.gps_clamp_height = p.get("gps_clamp_height", true);
  d.geotag_time_match = p.get("geotag_time_match", true);
  d.state_history_s = p.number("state_history", 10.0, 0.5, 600);
  d.laser_target_period_s = p.number("laser_target_period", 1.0, 0, 3600);
  d.silence_timeout_s = p.number("silence_timeout", 0.5, 0.1, 60);
  d.link_timeout_s = p.number("link_timeout", 3.0, 0.1, 600);

  c.ids = FrameIds(p.get<std::string>("frame_prefix", "k40t_"),
                   p.get<std::string>("joint_prefix", "k40t_"));
  c.publish_tf = p.get("publish_tf", true);
  c.geometry.tele = p.xyz("tele_offset", c.geometry.tele);
  c.geometry.wide = p.xyz("wide_offset", c.geometry.wide);
  c.geometry.thermal = p.xyz("thermal_offset", c.geometry.thermal);
  c.geometry.laser = p.xyz("laser_offset", c.geometry.laser);
  c.range.min_range = static_cast<float>(p.number("laser_min_range", 5.0, 0, 1e5));
  c.range.max_range = static_cast<float>(p.number("laser_max_range", 1500.0, 0, 1e5));
  c.range.field_of_view = static_cast<float>(p.number("laser_field_of_view", 0.003, 0, 3.2));
  c.rate_tolerance = p.number("rate_tolerance", 0.5, 0.01, 0.99);
  const std::string drive = p.get<std::string>("look_at_drive", "angle");
  if (drive != "angle" && drive != "rate")
    p.fail("look_at_drive", "must be angle or rate, got '" + drive + "'");
  c.look_at.control.drive = drive == "rate" ? LookAtDrive::kRate : LookAtDrive::kAngle;
  c.look_at.control.lead_s = p.number("look_at_lead", c.look_at.control.lead_s, 0, 1);
  c.look_at.control.limits.yaw_continuous = p.get("gimbal_yaw_continuous", false);
  c.look_at.rate_hz = p.number("look_at_rate", 20, 10, 50);
  c.look_at.point_timeout_s = p.number("look_at_point_timeout", 1.0, 0.1, 60);

  if (!p.error().empty()) return Result<RosPodConfig>::fail(p.error());
  return c;
}

}  // namespace k40t::driver
