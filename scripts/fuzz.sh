#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/*.cpp) with clang into build/fuzz and runs each of them.
#
#   scripts/fuzz.sh [--seconds N | --runs N] [--junit DIR] [target ...]
#
#   --seconds N  run each target for N seconds (default 10)
#   --runs N     run each target for N executions instead (e.g. --runs 10000000)
#   --junit DIR  write DIR/<target>.xml, one JUnit test case per target: pass = no crash
#   target       fuzz_parser, fuzz_decoders, ... (default: every fuzz/*.cpp)
#
# The seed corpus is made from the golden frames (scripts/make_fuzz_corpus.py); what the fuzzer
# discovers is kept in build/fuzz/corpus/<target> for the next run. A crash leaves its input in
# build/fuzz/artifacts/<target>/ (replay it with build/fuzz/bin/<target> <file>). Logs:
# build/fuzz/logs/<target>.log. Exit status: non-zero if a target crashed or did not build.
set -uo pipefail
source "$(dirname "$0")/env.sh"

limit=(-max_total_time=10)
junit=""
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) limit=(-max_total_time="$2"); shift 2 ;;
    --runs) limit=(-runs="$2"); shift 2 ;;
    --junit) junit="$2"; shift 2 ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done

build="$K40T_BUILD/fuzz"
mkdir -p "$build/logs"
[ -n "$junit" ] && mkdir -p "$junit"

# One JUnit file per target. $1 target, $2 seconds, $3 failure message or "", $4 summary, $5 log.
write_junit() {
  [ -n "$junit" ] || return 0
  /usr/bin/python3 - "$junit/$1.xml" "$1" "$2" "$3" "$4" "$5" <<'PY'
import sys, xml.etree.ElementTree as ET
path, name, seconds, failure, summary, log = sys.argv[1:7]
suite = ET.Element("testsuite", name="fuzz", tests="1", failures="1" if failure else "0", time=seconds)
case = ET.SubElement(suite, "testcase", classname="fuzz", name=name, time=seconds)
if failure:
    tail = ""
    try:
        tail = "".join(open(log, errors="replace").readlines()[-60:])
    except OSError:
        pass
    ET.SubElement(case, "failure", message=failure).text = tail
ET.SubElement(case, "system-out").text = summary
ET.ElementTree(suite).write(path, encoding="unicode", xml_declaration=True)
PY
}

if [ ${#targets[@]} -eq 0 ]; then
  for source in "$K40T_ROOT"/fuzz/*.cpp; do targets+=("$(basename "$source" .cpp)"); done
fi

# Only the fuzz targets and what they link: the simulator, tools and video are not fuzzed, and
# building them again with the sanitizers would only cost time.
echo "fuzz: building into $build"
if ! { cmake -S "$K40T_ROOT" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
         -DK40T_WITH_ROS=OFF -DK40T_BUILD_TESTS=OFF -DK40T_BUILD_FUZZ=ON > "$build/logs/configure.log" 2>&1 &&
       cmake --build "$build" -j "$JOBS" --target "${targets[@]}" > "$build/logs/build.log" 2>&1; }; then
  tail -n 40 "$build/logs/configure.log" "$build/logs/build.log"
  for t in "${targets[@]}"; do write_junit "$t" 0 "build failed" "" "$build/logs/build.log"; done
  exit 1
fi

rm -rf "$build/seeds"
/usr/bin/python3 "$K40T_ROOT/scripts/make_fuzz_corpus.py" "$build/seeds" || exit 1

status=0
printf '%-16s %14s %10s %8s  %s\n' target executions exec/s seconds result
for t in "${targets[@]}"; do
  bin="$build/bin/$t"
  log="$build/logs/$t.log"
  if [ ! -x "$bin" ]; then
    echo "fuzz: no target $t" >&2
    write_junit "$t" 0 "no such fuzz target" "" "$log"
    status=1
    continue
  fi
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t" "$build/seeds/$t"
  start=$(date +%s.%N)
  # -rss_limit_mb guards against runaway memory; -print_final_stats gives the figures below.
  "$bin" "${limit[@]}" -print_final_stats=1 -rss_limit_mb=2048 -artifact_prefix="$build/artifacts/$t/" \
    "$build/corpus/$t" "$build/seeds/$t" > "$log" 2>&1
  rc=$?
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  runs=${runs:-0}
  rate=${rate:-0}
  summary="$runs executions in ${seconds%.*}s ($rate exec/s); corpus $(ls "$build/corpus/$t" | wc -l) files"
  if [ $rc -eq 0 ]; then
    result=ok
    write_junit "$t" "$seconds" "" "$summary" "$log"
  else
    result="CRASH (exit $rc), see $log and $build/artifacts/$t/"
    write_junit "$t" "$seconds" "$t crashed (exit $rc)" "$summary" "$log"
    grep -m 5 -E "ERROR|invariant|runtime error|round trip|==[0-9]+==" "$log" >&2
    status=1
  fi
  printf '%-16s %14s %10s %8.1f  %s\n' "$t" "$runs" "$rate" "$seconds" "$result"
done
exit $status
