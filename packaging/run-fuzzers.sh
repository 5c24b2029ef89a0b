#!/usr/bin/env bash
# Builds the libFuzzer targets of the protocol parsers with Clang (ASan + UBSan) in their own
# build dir and runs each for a while. CI runs it briefly from run-tests.sh; for a long run give
# more seconds per target, e.g.  bash packaging/run-fuzzers.sh 3600
# New corpus entries go to <build>/corpus/<target>/ and crashes to <build>/artifacts/.
# `run-fuzzers.sh --build-only` configures and builds them and stops there (run-tests.sh builds
# them so beside the tests; the run after it finds them built).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ARMTRACK_FUZZ_BUILD_DIR:-$root/build-fuzz}"
build_only=false
if [ "${1:-}" = --build-only ]; then
  build_only=true
  shift
fi
seconds="${1:-10}"
targets=(fuzz_shimmer3 fuzz_lineimu fuzz_ngimu fuzz_skeleton fuzz_webcam_frame fuzz_recording fuzz_chunk)

cxx="$(command -v clang++ || command -v clang++-14 || true)"
cc="$(command -v clang || command -v clang-14 || true)"
if [ -z "$cxx" ] || [ -z "$cc" ]; then
  echo "run-fuzzers: clang not found (packaging/deps-debian12.sh installs it)" >&2
  exit 1
fi

# Line tables are all a sanitizer's report needs; full debug information would put a copy of
# the core library's in every fuzzer.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" \
  -DARMTRACK_BUILD_FUZZERS=ON >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}"
if $build_only; then
  exit 0
fi

mkdir -p "$build/artifacts"
# One fuzzer per core at a time (each is one process on one core, so each still gets its seconds
# of a whole core); the results are printed in the order of the list.
jobs="${ARMTRACK_FUZZ_JOBS:-$(nproc)}"
fuzz() {
  local t="$1"
  mkdir -p "$build/corpus/$t"
  # The first corpus dir collects new inputs; the seeds in the tree are only read.
  "$build/tests/fuzz/$t" "$build/corpus/$t" "$root/tests/fuzz/corpus/$t" \
    -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=1024 \
    -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" >"$build/$t.log" 2>&1
}
running=0
for t in "${targets[@]}"; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
  rm -f "$build/$t.status"
  { if fuzz "$t"; then echo ok; else echo failed; fi >"$build/$t.status"; } &
  running=$((running + 1))
done
wait
status=0
for t in "${targets[@]}"; do
  log="$build/$t.log"
  if [ "$(cat "$build/$t.status" 2>/dev/null)" = ok ]; then
    runs="$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')"
    echo "run-fuzzers: $t ok, ${runs:-?} executions in ${seconds} s"
  else
    echo "run-fuzzers: $t FAILED; last lines of $log:" >&2
    tail -n 40 "$log" >&2
    status=1
  fi
done
exit "$status"
