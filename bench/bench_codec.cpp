// Payload codec throughput (Google Benchmark): encode_payload() (validate + encode) and
// decode_payload() of one message per family, with a few fields set so nothing is all zeros.
// Figures: ns per call; items_per_second = messages per second. Run before and after a change to
// the message codec to show it is no slower.
#include <benchmark/benchmark.h>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/protocol/messages/sbus.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace {

namespace p = k40t::protocol;

// Each loop is a function of its own starting on a 64-byte line: where the compiler happened to
// place it moved a figure more than the codec did (LaserRangeAck decode 2.0 or 2.7 ns for the same
// instructions, the loop at 0 or 0x30 mod 64), so a change elsewhere showed as one in the codec.
template <class T>
[[gnu::noinline, gnu::aligned(64)]] void encode_loop(benchmark::State& state, const T& message) {
  for (auto _ : state) {
    auto payload = p::encode_payload(message);
    benchmark::DoNotOptimize(payload);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}

template <class T>
[[gnu::noinline, gnu::aligned(64)]] void decode_loop(benchmark::State& state, const T& message) {
  const auto payload = p::encode_payload(message);
  if (!payload) {
    state.SkipWithError(payload.error().c_str());
    return;
  }
  for (auto _ : state) {
    auto decoded = p::decode_payload<T>(payload->data(), payload->size);
    benchmark::DoNotOptimize(decoded);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}

p::LaserRangeAck laser_ack() {
  p::LaserRangeAck m;
  m.distance_m = 87.6;
  return m;
}
p::SbusConfigAck sbus_ack() {
  p::SbusConfigAck m;
  m.range.max_value = 1800;
  m.channels.yaw_channel = 9;
  return m;
}
p::ThermalStatus thermal_status() {
  p::ThermalStatus m;
  m.max_degC = 41.5;
  m.min_degC = -3.2;
  m.center_degC = 20.1;
  m.max_x_px = 100;
  m.point_y_px = 200;
  m.low_alarm = true;
  return m;
}
p::ThermalSettingsAck thermal_settings() {
  p::ThermalSettingsAck m;
  m.sharpness = 50;
  m.denoise_on = true;
  m.denoise_level = 3;
  m.high_alarm_degC = 80.5;
  return m;
}
p::VisibleSettingsAck visible_settings() {
  return p::VisibleSettingsAck{};
}
p::GimbalAttitude gimbal_attitude() {
  p::GimbalAttitude m;
  m.joint_yaw_deg = 12.34;
  m.pitch_deg = -45;
  m.yaw_rate_deg_s = 10.5;
  return m;
}

p::CameraSystemStatus camera_system_status() {
  p::CameraSystemStatus m;
  m.capture_mode = p::CaptureMode::kVideo;
  m.time_lapse_interval_s = 30;
  m.sd_total_mb = 64000;
  m.sd_free_mb = 12340;
  m.sd_used_mb = 51660;
  return m;
}
p::TakePhotoRequest take_photo() {
  p::TakePhotoRequest m;
  m.folder = "survey_0412";
  m.name = "ridge_north";
  return m;
}

#define K40T_CODEC_BENCH(Name, make)              \
  void BM_Encode##Name(benchmark::State& state) { \
    encode_loop(state, make());                   \
  }                                               \
  BENCHMARK(BM_Encode##Name);                     \
  void BM_Decode##Name(benchmark::State& state) { \
    decode_loop(state, make());                   \
  }                                               \
  BENCHMARK(BM_Decode##Name)

K40T_CODEC_BENCH(LaserRangeAck, laser_ack);
K40T_CODEC_BENCH(SbusConfigAck, sbus_ack);
K40T_CODEC_BENCH(ThermalStatus, thermal_status);
K40T_CODEC_BENCH(ThermalSettingsAck, thermal_settings);
K40T_CODEC_BENCH(VisibleSettingsAck, visible_settings);
K40T_CODEC_BENCH(GimbalAttitude, gimbal_attitude);
K40T_CODEC_BENCH(CameraSystemStatus, camera_system_status);
K40T_CODEC_BENCH(TakePhotoRequest, take_photo);

}  // namespace

BENCHMARK_MAIN();
