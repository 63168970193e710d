// The whole simulated pod, protocol-free: gimbal, telephoto zoom, thermal camera, laser, camera
// system (modes, photos, recordings, SD card, clock), and the system settings (versions, IP,
// SBUS, AI, power). step(dt) advances everything in model time — no wall clock, no threads — and
// queues the events (status frames, GPS requests) the front-end turns into frames.
//
// The sub-models are reachable for commands (gimbal().move(...)); what involves several of them
// (where the boresight points in the world, thermal stats, laser range, exposure, power and
// factory reset, the target geolocation) lives here.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "k40t_driver/sim/camera_model.h"
#include "k40t_driver/sim/events.h"
#include "k40t_driver/sim/gimbal_model.h"
#include "k40t_driver/sim/ground_truth.h"
#include "k40t_driver/sim/laser_model.h"
#include "k40t_driver/sim/model_part.h"
#include "k40t_driver/sim/thermal_model.h"
#include "k40t_driver/sim/world.h"
#include "k40t_driver/sim/zoom_model.h"

namespace k40t::sim {

struct Version {
  uint8_t major = 0;
  uint8_t minor = 0;
  uint8_t patch = 0;
};

struct Versions {
  Version gimbal_hardware{1, 2, 0};
  Version gimbal_software{3, 4, 1};
  Version camera{2, 1, 7};
};

using Ipv4 = std::array<uint8_t, 4>;
struct NetworkSettings {  // 0x000311 / 0x000312, section 2.3.1 default address
  bool dynamic = false;
  Ipv4 address{192, 168, 144, 64};
  Ipv4 netmask{255, 255, 255, 0};
  Ipv4 gateway{192, 168, 144, 1};
};

struct SbusSettings {  // 0x000500..0x000502
  uint16_t max_value = 1811;
  uint16_t min_value = 172;
  // Channels (0..15 = channels 1..16) for: stream, zoom, photo, video, pitch, yaw, centre.
  std::array<uint8_t, 7> channels{0, 1, 2, 3, 4, 5, 6};
};

struct TrackingBox {
  uint16_t x = 0;
  uint16_t y = 0;
  uint16_t width = 0;
  uint16_t height = 0;
};

struct AiSettings {  // 0x000319 / 0x000324
  bool recognition_on = false;
  uint8_t model = 0;
  std::array<uint8_t, 10> classes{};
  bool tracking = false;
  TrackingBox box;
};

// Self-test bits of 0x000001 byte 3.
enum SelfTestBit : uint8_t {
  kSelfTestInfrared = 1 << 0,
  kSelfTestTele = 1 << 1,
  kSelfTestWide = 1 << 2,
  kSelfTestLaser = 1 << 3,
};
constexpr uint8_t kSelfTestAllGood =
    kSelfTestInfrared | kSelfTestTele | kSelfTestWide | kSelfTestLaser;

struct PodConfig {
  WorldConfig world;
  GimbalConfig gimbal;
  ZoomConfig zoom;
  LaserConfig laser;
  CameraConfig camera;
  VehicleConfig vehicle;
  Versions versions;
  double camera_boot_s = 5;  // after shutdown or factory reset
  double reset_delay_s = 1;  // 0x00030F: "restart after one second"
};

// What 0x000005 reports about exposure: the settings, or in auto what auto exposure chose.
struct Exposure {
  uint8_t ev_code = 0;
  double iso_db = 0;
  double shutter_us = 0;
};

class PodModel {
 public:
  explicit PodModel(const PodConfig& config = {});

  void step(double dt_s);
  EventQueue take_events();
  double now_s() const { return now_s_; }

  K40T_MODEL_PART(GimbalModel, gimbal)
  K40T_MODEL_PART(ZoomModel, zoom)
  K40T_MODEL_PART(ThermalModel, thermal)
  K40T_MODEL_PART(LaserModel, laser)
  K40T_MODEL_PART(CameraModel, camera)
  K40T_MODEL_PART(World, world)

  // Where the boresight points in the world frame.
  double boresight_yaw_deg() const;
  double boresight_pitch_deg() const;
  // The attitude 0x000002 reports (stabilised: world heading, level vehicle).
  double attitude_yaw_deg() const { return wrap_deg(boresight_yaw_deg()); }

  ThermalStats thermal_stats() const;
  std::optional<double> laser_range() const;
  Exposure exposure() const;

  // The truth: the vehicle's motion, the pod's, the objects' and the laser spot's true
  // positions (truth frame of ground_truth.h), and the geotag log. The Unix time of model time 0
  // is the front-end's to set (the model has no clock).
  GroundTruth& ground_truth() { return truth_; }
  const GroundTruth& ground_truth() const { return truth_; }
  Vec3 pod_position() const { return truth_.pod_position(now_s_, world_.config().ground_height_m); }
  Vec3 hot_object_position() const { return pod_position() + world_.hot_object_centre(); }
  std::optional<Vec3> laser_spot() const;
  void set_unix_epoch_s(double seconds) { unix_epoch_s_ = seconds; }
  double unix_time_s() const { return unix_epoch_s_ + now_s_; }

  // 0x000320: the host's fix and attitude (degrees) in, the laser target's position out. Only
  // the vehicle's heading turns the world.
  std::optional<GeoPoint> locate_target(const GeoPoint& host, const YawPitchRoll& attitude_deg);
  const YawPitchRoll& vehicle_attitude_deg() const { return vehicle_deg_; }

  const Versions& versions() const { return config_.versions; }
  K40T_MODEL_PART(NetworkSettings, network)
  Outcome set_network(const NetworkSettings& settings);
  const SbusSettings& sbus() const { return sbus_; }
  Outcome set_sbus_range(int max_value, int min_value);
  Outcome set_sbus_channels(const std::array<uint8_t, 7>& channels);
  const AiSettings& ai() const { return ai_; }
  Outcome set_ai(bool on, uint8_t model, const std::array<uint8_t, 10>& classes);
  Outcome set_tracking(bool on, const TrackingBox& box);

  Outcome shutdown();       // 0x000316: the camera goes down, and boots again after camera_boot_s
  Outcome factory_reset();  // 0x00030F: after reset_delay_s, defaults and a reboot
  bool camera_available() const { return camera_off_s_ <= 0; }
  bool camera_link_ok() const { return camera_available(); }
  bool gimbal_link_ok() const { return !gimbal_.restarting(); }
  uint8_t upgrade_status() const { return camera_.upgrading() ? 0x02 : 0x00; }  // 0x000001 byte 2
  uint8_t self_test() const { return self_test_; }
  void set_self_test(uint8_t bits) { self_test_ = bits; }

 private:
  void restore_defaults();
  void update_auto_exposure();

  PodConfig config_;
  World world_;
  GimbalModel gimbal_;
  ZoomModel zoom_;
  ThermalModel thermal_;
  LaserModel laser_;
  CameraModel camera_;
  NetworkSettings network_;
  SbusSettings sbus_;
  AiSettings ai_;
  YawPitchRoll vehicle_deg_;
  GroundTruth truth_;
  double unix_epoch_s_ = 0;
  uint8_t self_test_ = kSelfTestAllGood;
  double now_s_ = 0;
  double camera_off_s_ = 0;    // > 0: the camera is down for this long
  double shutdown_in_s_ = -1;  // >= 0: a shutdown/reset is pending
  bool reset_pending_ = false;
  double locked_shutter_us_ = 0;  // auto exposure's choice when AE lock went on
  EventQueue events_;
};

}  // namespace k40t::sim
