// PSDK layer costs: CRC16/CRC32 per byte, AES-128-ECB through EVP per frame, encoding a push into
// a frame, and the streaming parser on a realistic push stream (attitude, GPS, battery, ...).
#include <benchmark/benchmark.h>

#include <vector>

#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/psdk/crc.h"
#include "k40t_driver/psdk/frame.h"
#include "k40t_driver/psdk/parser.h"
#include "k40t_driver/psdk/sim/flight_model.h"
#include "k40t_driver/psdk/sim/pushes.h"

namespace {

using namespace k40t::psdk;

std::vector<uint8_t> bytes_of(size_t n) {
  std::vector<uint8_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = static_cast<uint8_t>(i * 31 + 7);
  return v;
}

void BM_Crc16(benchmark::State& state) {
  const auto data = bytes_of(static_cast<size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(crc16(data.data(), data.size()));
  state.SetBytesProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_Crc16)->Arg(10)->Arg(268);

void BM_Crc32(benchmark::State& state) {
  const auto data = bytes_of(static_cast<size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(crc32(data.data(), data.size()));
  state.SetBytesProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_Crc32)->Arg(12)->Arg(268);

void BM_AesEncrypt(benchmark::State& state) {
  const Aes128Ecb cipher(AesKey{1, 2, 3, 4});
  auto data = bytes_of(static_cast<size_t>(state.range(0)));
  for (auto _ : state) {
    (void)cipher.encrypt(data.data(), data.size(), data.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_AesEncrypt)->Arg(16)->Arg(256);

void BM_EncodeGpsPushFrame(benchmark::State& state) {
  const GpsPush push = sim::gps_push(sim::FlightModel().state_at(30), 14);
  FrameHeader h;
  h.command = GpsPush::key();
  for (auto _ : state) {
    const auto data = encode_data(push);
    const auto frame = encode_frame(h, data->data(), data->size);
    benchmark::DoNotOptimize(frame->data());
  }
}
BENCHMARK(BM_EncodeGpsPushFrame);

// One second of the simulator's pushes (50 attitude, 5 GPS, 5 raw GPS, 5 RTK, 10 baro, 1 each of
// the rest), fed in 64-byte reads as a UART driver would deliver them.
void BM_ParsePushStream(benchmark::State& state) {
  std::vector<uint8_t> stream;
  const sim::FlightModel model;
  const auto add = [&](CommandKey key, const k40t::Result<Data>& data) {
    FrameHeader h;
    h.command = key;
    const auto f = encode_frame(h, data->data(), data->size);
    stream.insert(stream.end(), f->data(), f->data() + f->size());
  };
  for (int i = 0; i < 50; ++i) {
    const sim::AirframeState s = model.state_at(20 + i * 0.02);
    add(AttitudePush::key(), encode_data(sim::attitude_push(s)));
    if (i % 10 == 0) {
      add(GpsPush::key(), encode_data(sim::gps_push(s, 14)));
      add(RawGpsPush::key(), encode_data(sim::raw_gps_push(s, static_cast<uint16_t>(i))));
      add(RawRtkPush::key(), encode_data(sim::raw_rtk_push(s)));
    }
    if (i % 5 == 0)
      add(BarometricAltitudePush::key(), encode_data(sim::barometric_altitude_push(s)));
  }
  const sim::AirframeState s = model.state_at(21);
  add(BatteryInfoPush::key(), encode_data(sim::battery_push(s)));
  add(UavStatePush::key(), encode_data(sim::uav_state_push(s, DroneType::kM210RtkV2)));
  add(LinkBandwidthPush::key(), encode_data(sim::link_bandwidth_push(s)));
  add(UtcTimePush::key(), encode_data(sim::utc_time_push(s)));
  FrameParser parser;
  size_t frames = 0;
  for (auto _ : state) {
    for (size_t i = 0; i < stream.size(); i += 64) {
      parser.feed(stream.data() + i, std::min<size_t>(64, stream.size() - i),
                  [&](const FrameView&) { ++frames; });
    }
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * stream.size()));
  state.counters["bytes_per_second_of_flight"] = static_cast<double>(stream.size());
  state.counters["frames"] =
      benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ParsePushStream);

}  // namespace

BENCHMARK_MAIN();
