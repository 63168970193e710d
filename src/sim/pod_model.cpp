#include "k40t_driver/sim/pod_model.h"

#include <cmath>
#include <utility>

namespace k40t::sim {

namespace {
constexpr double kShutdownGraceS = 0.2;  // lets the ACK of 0x000316 leave before the camera goes

// Exposure compensation of an EV code (3.2.3.6), in stops.
double ev_stops(uint8_t code) {
  switch (code) {
    case 0x0A:
      return 2;
    case 0x10:
      return 1;
    case 0x1C:
      return -1;
    case 0x23:
      return -2;
    default:
      return 0;  // auto, 0
  }
}
}  // namespace

PodModel::PodModel(const PodConfig& config)
    : config_(config),
      world_(config.world),
      gimbal_(config.gimbal),
      zoom_(config.zoom),
      laser_(config.laser),
      camera_(config.camera),
      truth_(config.vehicle) {
  update_auto_exposure();
}

double PodModel::boresight_yaw_deg() const {
  return vehicle_deg_.yaw + gimbal_.pose().joint_deg.yaw;
}
double PodModel::boresight_pitch_deg() const {
  return gimbal_.pose().joint_deg.pitch;
}

ThermalStats PodModel::thermal_stats() const {
  return thermal_.measure(world_, boresight_yaw_deg(), boresight_pitch_deg());
}

std::optional<double> PodModel::laser_range() const {
  return laser_.range(world_, boresight_yaw_deg(), boresight_pitch_deg());
}

std::optional<Vec3> PodModel::laser_spot() const {
  const std::optional<double> range = laser_range();
  if (!range) return std::nullopt;
  return pod_position() + direction(boresight_yaw_deg(), boresight_pitch_deg()) * *range;
}

Exposure PodModel::exposure() const {
  const VisibleSettings& v = camera_.visible();
  Exposure e;
  e.ev_code = static_cast<uint8_t>(v.ev);
  e.iso_db = iso_code_db(static_cast<uint8_t>(v.iso));
  e.shutter_us = v.shutter != protocol::Shutter::kAuto
                     ? shutter_code_us(static_cast<uint8_t>(v.shutter))
                     : locked_shutter_us_;
  return e;
}

std::optional<GeoPoint> PodModel::locate_target(const GeoPoint& host,
                                                const YawPitchRoll& attitude_deg) {
  vehicle_deg_ = attitude_deg;
  return laser_.locate_target(world_, host, boresight_yaw_deg(), boresight_pitch_deg());
}

Outcome PodModel::set_network(const NetworkSettings& settings) {
  if (!settings.dynamic && (settings.address[0] == 0 || settings.address[0] >= 224))
    return Outcome::kFailure;
  network_ = settings;
  return Outcome::kOk;
}

Outcome PodModel::set_sbus_range(int max_value, int min_value) {
  if (max_value < 0 || max_value > 2047 || min_value < 0 || min_value >= max_value)
    return Outcome::kFailure;
  sbus_.max_value = static_cast<uint16_t>(max_value);
  sbus_.min_value = static_cast<uint16_t>(min_value);
  return Outcome::kOk;
}

Outcome PodModel::set_sbus_channels(const std::array<uint8_t, 7>& channels) {
  for (uint8_t channel : channels) {
    if (channel > 15) return Outcome::kFailure;
  }
  sbus_.channels = channels;
  return Outcome::kOk;
}

Outcome PodModel::set_ai(bool on, uint8_t model, const std::array<uint8_t, 10>& classes) {
  ai_.recognition_on = on;
  ai_.model = model;
  ai_.classes = classes;
  if (!on) {
    ai_.tracking = false;
    gimbal_.stop_tracking();
  }
  return Outcome::kOk;
}

Outcome PodModel::set_tracking(bool on, const TrackingBox& box) {
  // 3.2.4.25 note: AI detection must be on to track a box.
  if (on && !ai_.recognition_on) return Outcome::kFailure;
  if (on && (box.width == 0 || box.height == 0 || box.x + box.width > 1920 ||
             box.y + box.height > 1080)) {
    return Outcome::kFailure;
  }
  if (!on) {
    gimbal_.stop_tracking();
    ai_.tracking = false;
    return Outcome::kOk;
  }
  // The box is drawn on the telephoto picture as it is now.
  const Outcome tracking = gimbal_.start_tracking(
      Lens::kTele, zoom_.zoom(), box.x + box.width / 2.0, box.y + box.height / 2.0);
  if (tracking != Outcome::kOk) return tracking;
  ai_.tracking = true;
  ai_.box = box;
  return Outcome::kOk;
}

Outcome PodModel::shutdown() {
  if (shutdown_in_s_ >= 0) return Outcome::kBusy;
  shutdown_in_s_ = kShutdownGraceS;
  return Outcome::kOk;
}

Outcome PodModel::factory_reset() {
  if (shutdown_in_s_ >= 0) return Outcome::kBusy;
  shutdown_in_s_ = config_.reset_delay_s;
  reset_pending_ = true;
  return Outcome::kOk;
}

void PodModel::restore_defaults() {
  thermal_.settings() = ThermalSettings{};
  camera_.restore_defaults();
  zoom_.reset();
  laser_.set_periodic(false);
  network_ = NetworkSettings{};
  sbus_ = SbusSettings{};
  ai_ = AiSettings{};
}

void PodModel::step(double dt_s) {
  now_s_ += dt_s;
  const Vec3 pod = pod_position();
  world_.set_pod_offset(pod.x, pod.y);
  if (shutdown_in_s_ >= 0) {
    shutdown_in_s_ -= dt_s;
    if (shutdown_in_s_ < 0) {
      camera_.abort_activity();
      if (reset_pending_) restore_defaults();
      reset_pending_ = false;
      camera_off_s_ = config_.camera_boot_s;
    }
  } else if (camera_off_s_ > 0) {
    camera_off_s_ = std::max(0.0, camera_off_s_ - dt_s);
  }
  gimbal_.step(dt_s, events_);
  zoom_.step(dt_s, events_);
  camera_.step(dt_s, zoom_.zooming() || zoom_.focusing(), events_);
  if (!camera_.visible().ae_lock_on) update_auto_exposure();
}

void PodModel::update_auto_exposure() {
  // The sky is brighter than the ground; EV shifts the choice by whole stops.
  const bool sky =
      world_.trace(direction(boresight_yaw_deg(), boresight_pitch_deg())).surface == Surface::kSky;
  locked_shutter_us_ =
      (sky ? 500.0 : 2000.0) * std::pow(2.0, ev_stops(static_cast<uint8_t>(camera_.visible().ev)));
}

EventQueue PodModel::take_events() {
  EventQueue out;
  std::swap(out, events_);
  return out;
}

}  // namespace k40t::sim
