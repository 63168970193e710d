#include "k40t_driver/ros/video/video_config.h"

#include "k40t_driver/ros/param_reader.h"

namespace k40t::driver {

namespace {

template <class T>
T parsed(ParamReader& p, const std::string& name, const std::string& fallback,
         Result<T> (*parse)(const std::string&), T default_value) {
  Result<T> value = parse(p.get<std::string>(name, fallback));
  if (!value) {
    p.fail(name, value.error());
    return default_value;
  }
  return value.value();
}

Result<video::Lens> parse_lens(const std::string& name) {
  if (name == "tele") return video::Lens::kTele;
  if (name == "wide") return video::Lens::kWide;
  if (name == "thermal") return video::Lens::kThermal;
  return Result<video::Lens>::fail("lens '" + name + "' is not one of: tele, wide, thermal");
}

NominalOptics optics(ParamReader& p, const std::string& lens, const NominalOptics& fallback) {
  return {p.number(lens + "_focal_length", fallback.focal_length_mm, 0.1, 1000),
          p.number(lens + "_sensor_width", fallback.sensor_width_mm, 0.1, 100)};
}

}  // namespace

Result<VideoConfig> read_video_config(const ros::NodeHandle& private_nh) {
  ParamReader p(private_nh);
  VideoConfig c;
  video::CaptureOptions& capture = c.capture;
  capture.url = p.get<std::string>("url", capture.url);
  capture.backend = parsed(p, "backend", "gstreamer", &video::parse_backend, capture.backend);
  capture.low_latency = p.get("low_latency", capture.low_latency);
  capture.transport = parsed(p, "transport", "tcp", &video::parse_transport, capture.transport);
  capture.open_timeout_s = p.number("open_timeout", capture.open_timeout_s, 0.1, 60);
  capture.read_timeout_s = p.number("read_timeout", capture.read_timeout_s, 0.1, 60);
  if (Status s = video::validate(capture); !s) p.fail("url", s.message());

  c.stamps.latency_s = p.number("latency", 0.075, 0, 5);
  c.stamps.use_presentation_time = p.get("use_presentation_time", false);
  c.stamps.window_s = p.number("stamp_window", c.stamps.window_s, 0.1, 600);

  c.frame_prefix = p.get<std::string>("frame_prefix", c.frame_prefix);
  c.mode6_lens = parsed(p, "image_mode_6_lens", "tele", &parse_lens, c.mode6_lens);
  c.calibration_urls = {p.get<std::string>("camera_info_url_tele", ""),
                        p.get<std::string>("camera_info_url_wide", ""),
                        p.get<std::string>("camera_info_url_thermal", "")};
  c.tele = optics(p, "tele", c.tele);
  c.wide = optics(p, "wide", c.wide);
  c.thermal = optics(p, "thermal", c.thermal);
  c.tele_max_optical_zoom = p.number("tele_max_optical_zoom", c.tele_max_optical_zoom, 1, 200);
  c.tele_calibration_focal_length_mm =
      p.number("tele_calibration_focal_length", c.tele.focal_length_mm, 0.1, 2000);
  c.wide_digital_zoom = p.number("wide_digital_zoom", c.wide_digital_zoom, 1, 8);
  c.settings_topic = p.get<std::string>("settings_topic", c.settings_topic);
  c.expected_fps = p.number("expected_fps", c.expected_fps, 1, 240);
  c.stale_after_s = p.number("stale_after", c.stale_after_s, 0.05, 60);
  c.diagnostic_period_s = p.number("diagnostic_period", c.diagnostic_period_s, 0.05, 10);
  if (!p.error().empty()) return Result<VideoConfig>::fail(p.error());
  return c;
}

std::string optical_frame(const VideoConfig& config, video::Lens lens) {
  return config.frame_prefix + video::to_string(lens) + "_optical_frame";
}

}  // namespace k40t::driver
