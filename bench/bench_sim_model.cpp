// What the simulated pod costs per step of its tick loop: the model step, one thermal
// measurement (the 5 Hz report's ray casting), the encoding of every periodic report, and one
// request answered. The server steps every 10 ms, so a step plus its share of reports must stay
// far below 10 ms for the simulator to keep real time on a busy test machine.
#include <benchmark/benchmark.h>

#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/sim/pod_model.h"
#include "k40t_driver/sim/pod_reports.h"
#include "k40t_driver/sim/request_handlers.h"

namespace {

using namespace k40t;

void BM_ModelStep(benchmark::State& state) {
  sim::PodModel pod;
  (void)pod.gimbal().move(sim::YawMotion::kRight, sim::PitchMotion::kDown);
  (void)pod.zoom().zoom_control(sim::ContinuousZoom::kIn);
  for (auto _ : state) {
    pod.step(0.01);
    benchmark::DoNotOptimize(pod.take_events());
  }
}
BENCHMARK(BM_ModelStep);

void BM_ThermalMeasurement(benchmark::State& state) {
  sim::PodModel pod;
  const sim::Vec3 hot = pod.world().hot_object_centre();
  (void)pod.gimbal().set_dial_speed(30, 30);
  (void)pod.gimbal().command_angles(sim::pitch_of(hot), sim::yaw_of(hot));
  for (int i = 0; i < 300; ++i) pod.step(0.01);
  for (auto _ : state) benchmark::DoNotOptimize(pod.thermal_stats());
}
BENCHMARK(BM_ThermalMeasurement)->Unit(benchmark::kMicrosecond);

void BM_EveryPeriodicReport(benchmark::State& state) {
  sim::PodModel pod;
  pod.laser().set_periodic(true);
  const protocol::CodecOptions codec;
  for (auto _ : state) {
    for (const sim::PeriodicReport& report : sim::periodic_reports()) {
      benchmark::DoNotOptimize(report.encode(pod, codec));
    }
  }
}
BENCHMARK(BM_EveryPeriodicReport)->Unit(benchmark::kMicrosecond);

void BM_AnswerRequest(benchmark::State& state) {
  sim::PodModel pod;
  const protocol::CodecOptions codec;
  protocol::ZoomRatioRequest request;
  request.zoom_x = 8;
  const auto payload = protocol::encode_payload(request, codec);
  protocol::FrameView frame;
  frame.header.message_id = protocol::ZoomRatioRequest::kId;
  frame.payload = payload->data();
  frame.payload_size = payload->size;
  for (auto _ : state) benchmark::DoNotOptimize(sim::answer_request(pod, codec, frame));
}
BENCHMARK(BM_AnswerRequest);

}  // namespace

BENCHMARK_MAIN();
