#!/usr/bin/env bash
# Sets up a Debian 12 machine, builds ArmTrack and runs every test (ctest labels unit,
# integration and, once the GUI exists, gui), then prints the benchmark figures.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ARMTRACK_BUILD_DIR:-$root/build}"
# The seconds since the start at the end of each phase, printed as it ends and listed again on
# exit (a failure included), so the next change to the CI's length knows where the time goes.
phases=""
phase() {
  phases="$phases$(printf '%-12s %5d s' "$1" "$SECONDS")\n"
  echo "run-tests: $1 done at ${SECONDS} s" >&2
}
trap 'printf "run-tests: phases (seconds since start):\n$phases" >&2' EXIT

bash "$root/packaging/deps-debian12.sh"
phase deps
# The same configuration as run-app.sh (Release -O2, warnings as errors), plus the tests; of the
# benchmarks only those run below (tests/benchmarks/CMakeLists.txt).
bash "$root/packaging/configure-build.sh" "$root" "$build" -DBUILD_TESTING=ON \
  -DARMTRACK_ALL_BENCHMARKS=OFF
cmake --build "$build" --parallel "$(nproc)"
phase build

# Benchmarks are figures, not pass/fail: print them before the test summary. bench_filter warms
# each filter up once and cycles through 20 s of data (14 s of CPU in all at 0.05 s of timed steps
# per figure, where warming up again on every call and every 2 s took 68 s); give more for
# steadier figures.
if [ -x "$build/tests/benchmarks/bench_filter" ]; then
  "$build/tests/benchmarks/bench_filter" --benchmark_min_time=0.05 || echo "benchmarks failed to run" >&2
fi
# The clinical records on SQLite and on a PostgreSQL server the benchmark starts itself.
if [ -x "$build/tests/benchmarks/bench_storage" ]; then
  "$build/tests/benchmarks/bench_storage" --benchmark_min_time=0.3 ||
    echo "storage benchmarks failed to run" >&2
fi

# session import and report of hostile files and of an hour at 1 kHz, as child processes: wall
# time, CPU and peak memory against issue 24's targets (about a minute).
if [ -x "$build/tests/benchmarks/bench_import" ]; then
  "$build/tests/benchmarks/bench_import" --cli "$build/app/armtrack-cli" ||
    echo "import benchmark failed to run" >&2
fi
phase benchmarks

# The fuzzers' Clang build (run-fuzzers.sh below; 88 s of CPU, 44 s of the fuzzer phase at
# 3e4b6a9) runs beside the tests under the idle scheduling policy (SCHED_IDLE): it gets only the
# CPU time no test wants, and the tests leave plenty (a GUI test holding half a core uses about a
# third of one, test_session_trunk 3.6 s of CPU in a minute), so the tests keep the cores they
# asked CTest for. The fuzzer phase then finds the fuzzers built. In its own process group (setsid),
# so that it can be stopped whole.
# Whether a process of session $1 is left (from /proc: procps may not be installed).
session_alive() {
  local f line sid
  for f in /proc/[0-9]*/stat; do
    line="$(<"$f")" 2>/dev/null || continue
    read -r _ _ _ sid _ <<<"${line##*) }" # after the command name: state ppid pgrp session
    [ "$sid" = "$1" ] && return 0
  done
  return 1
}
setsid chrt --idle 0 bash "$root/packaging/run-fuzzers.sh" --build-only \
  >"$build/fuzz-build.log" 2>&1 &
fuzz_build=$!
trap 'kill -- "-$fuzz_build" 2>/dev/null || true; printf "run-tests: phases (seconds since start):\n$phases" >&2' EXIT

cd "$build"
# Ten CTest "cpu" slots per core, each a tenth of a core: a test that computes holds ten, one
# measured to wait part of its run (a GUI test paced by timers and the virtual arm, a session in
# real time) holds the tenths it was measured to use (tests/CMakeLists.txt), so the tests run side
# by side without asking more CPU than the cores give. At most four tests per core at once.
slots=$((10 * $(nproc)))
printf '{"version": {"major": 1, "minor": 0}, "local": [{"cpu": [{"id": "0", "slots": %d}]}]}\n' \
  "$slots" >"$build/ctest-resources.json"
ctest --output-on-failure --parallel "$((4 * $(nproc)))" \
  --resource-spec-file "$build/ctest-resources.json" --timeout 600
phase ctest
# What the tests left of that build is done at the normal priority by run-fuzzers.sh below, which
# also reports a failure: stop the idle one (ninja stops its compilers and deletes the outputs
# they were writing) and wait until nothing of its session is left, so that two ninjas never
# share the fuzzers' build dir.
kill -- "-$fuzz_build" 2>/dev/null || true
while session_alive "$fuzz_build"; do sleep 0.2; done
wait "$fuzz_build" 2>/dev/null || true

# A short libFuzzer run of every protocol parser (about a minute in all); the long run is the same
# script with more seconds per target.
bash "$root/packaging/run-fuzzers.sh" "${ARMTRACK_FUZZ_SECONDS:-10}"
phase fuzzers
