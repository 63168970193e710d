#!/usr/bin/env bash
# Builds build/core with the benchmarks and runs every bench program (build/core/bin/bench_*),
# printing all their figures. Where a benchmark's name contains "Baseline" and another one of the
# same program differs from it only in that word (e.g. BM_ParseMixedBaseline/64 and
# BM_ParseMixedFrameParser/64), the throughput ratio of the two is printed too.
#
#   scripts/bench.sh [extra Google Benchmark flags, e.g. --benchmark_filter=Parse]
#
# JSON results: build/core/bench/<program>.json. Figures are CPU-time rates; on a loaded machine
# run it twice and compare.
set -euo pipefail
source "$(dirname "$0")/env.sh"

"$K40T_ROOT/scripts/build.sh" core
out="$K40T_BUILD/core/bench"
mkdir -p "$out"
shopt -s nullglob
programs=("$K40T_BUILD"/core/bin/bench_*)
if [ ${#programs[@]} -eq 0 ]; then
  echo "bench.sh: no bench programs in $K40T_BUILD/core/bin" >&2
  exit 1
fi
for program in "${programs[@]}"; do
  name="$(basename "$program")"
  echo "== $name"
  "$program" --benchmark_out="$out/$name.json" --benchmark_out_format=json "$@"
  /usr/bin/python3 - "$out/$name.json" <<'PY'
import json, re, sys
# Plain runs, or with --benchmark_repetitions the means (named without their "_mean").
rate = {}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "mean":
        rate[b["run_name"]] = b.get("bytes_per_second")
    elif b.get("run_type") == "iteration" and b.get("repetitions", 1) <= 1:
        rate[b["name"]] = b.get("bytes_per_second")
for name, baseline in rate.items():
    if "Baseline" not in name or not baseline:
        continue
    pattern = re.compile(re.escape(name).replace("Baseline", r"(\w+)") + "$")
    for other, value in rate.items():
        m = pattern.match(other)
        if other != name and m and value:
            print("ratio %s / %s: %.2fx (%.0f vs %.0f MB/s)" % (other, name, value / baseline, value / 1e6, baseline / 1e6))
PY
done
