// Round-trip percentiles of the latency benchmarks (bench_session, bench_transport), reported as
// Google Benchmark counters in µs.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace k40t::bench {

// The value at `fraction` (0..1) of a sorted list, nearest rank; 0 for an empty list.
inline double percentile(const std::vector<double>& sorted, double fraction) {
  if (sorted.empty()) return 0.0;
  const auto index = static_cast<size_t>(fraction * static_cast<double>(sorted.size() - 1) + 0.5);
  return sorted[std::min(index, sorted.size() - 1)];
}

// Sets the counters p50_us, p99_us and max_us from round trips in µs.
inline void report_percentiles(benchmark::State& state, std::vector<double> micros) {
  std::sort(micros.begin(), micros.end());
  state.counters["p50_us"] = percentile(micros, 0.50);
  state.counters["p99_us"] = percentile(micros, 0.99);
  state.counters["max_us"] = micros.empty() ? 0.0 : micros.back();
}

}  // namespace k40t::bench
