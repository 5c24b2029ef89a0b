#!/usr/bin/env bash
# Sets up a Debian 12 machine, builds ArmTrack and runs every test (ctest labels unit,
# integration and, once the GUI exists, gui), then prints the benchmark figures.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ARMTRACK_BUILD_DIR:-$root/build}"

bash "$root/packaging/deps-debian12.sh"
# The test build carries no debug information. Every test executable links the core library
# statically, and with -g each held its own copy of that library's debug information (about
# 290 MB apiece, 12.7 GB for the build), which filled the CI machine's disk. -O2, as in the
# default RelWithDebInfo build, so the figures and the numerical results are the same.
# Warnings are errors here, so a change that adds one fails the tests (a user's build only warns).
cmake -S "$root" -B "$build" -G Ninja -DBUILD_TESTING=ON -DARMTRACK_GUI=ON \
  -DARMTRACK_WARNINGS_AS_ERRORS=ON -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O2 -DNDEBUG"
cmake --build "$build" --parallel "$(nproc)"

# Benchmarks are figures, not pass/fail: print them before the test summary.
if [ -x "$build/tests/benchmarks/bench_filter" ]; then
  "$build/tests/benchmarks/bench_filter" --benchmark_min_time=0.2 || echo "benchmarks failed to run" >&2
fi
# The clinical records on SQLite and on a PostgreSQL server the benchmark starts itself.
if [ -x "$build/tests/benchmarks/bench_storage" ]; then
  "$build/tests/benchmarks/bench_storage" --benchmark_min_time=1 ||
    echo "storage benchmarks failed to run" >&2
fi

cd "$build"
ctest --output-on-failure --parallel "$(nproc)" --timeout 600

# A short libFuzzer run of every protocol parser (about a minute in all); the long run is the same
# script with more seconds per target.
bash "$root/packaging/run-fuzzers.sh" "${ARMTRACK_FUZZ_SECONDS:-10}"
