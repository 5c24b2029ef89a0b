#!/usr/bin/env bash
# Configures the build folder that run-app.sh and run-tests.sh share, with the same settings for
# both, so running one after the other builds only what the second needs instead of recompiling
# everything under other flags.
#
# Release with -O2 and without debug information: every test executable links the core library
# statically, and with -g each held its own copy of that library's debug information (about
# 290 MB apiece, 12.7 GB for the test build), which filled the CI machine's disk. Warnings are
# errors, so a change that adds one fails CI; Debian 12's compiler is the only one these scripts
# build with. A plain `cmake -S . -B build` (see docs/packaging.md) keeps warnings as warnings.
#
# Usage: configure-build.sh SOURCE BUILD [extra cmake arguments]
set -euo pipefail
src="$1"
build="$2"
shift 2
cmake -S "$src" -B "$build" -G Ninja -DARMTRACK_GUI=ON -DARMTRACK_WARNINGS_AS_ERRORS=ON \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELEASE="-O2 -DNDEBUG" "$@"
