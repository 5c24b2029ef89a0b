#!/usr/bin/env bash
# Sets up a Debian 12 machine, builds ArmTrack and starts it. Until the GUI lands this runs a
# demo session through the command-line tool: a simulated recording of both IMUs, a Kinect and
# a webcam (the virtual devices' source), estimated and compared with the simulation's truth.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ARMTRACK_BUILD_DIR:-$root/build}"
data="${XDG_DATA_HOME:-$HOME/.local/share}/ArmTrack/demo"

bash "$root/packaging/deps-debian12.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$build" --parallel "$(nproc)" --target armtrack-cli

cli="$build/app/armtrack-cli"
mkdir -p "$data"
"$cli" simulate --trajectory multi-joint --duration 30 --webcam --out "$data/session.csv"
"$cli" estimate "$data/session.csv" --joint-accel-std 10 --out "$data/angles.csv"
echo "Recording and estimated angles are in $data"
