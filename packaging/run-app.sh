#!/usr/bin/env bash
# Sets up a Debian 12 machine, builds ArmTrack and starts it. Until the GUI lands this runs a
# demo session through the command-line tool: a 30 s live session with the virtual arm (both
# IMUs, a Kinect and a webcam, simulated in real time) through the device plugins, the time
# synchroniser and the estimator, recorded with the live angles and the simulation's truth,
# then re-estimated offline and compared with the truth.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ARMTRACK_BUILD_DIR:-$root/build}"
data="${XDG_DATA_HOME:-$HOME/.local/share}/ArmTrack/demo"

bash "$root/packaging/deps-debian12.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$build" --parallel "$(nproc)" --target armtrack-cli armtrack_plugin_virtual-arm

cli="$build/app/armtrack-cli"
mkdir -p "$data"
"$cli" record --device virtual-arm:sensors=upper+forearm+kinect+webcam --duration 30 \
  --out "$data/session.csv"
"$cli" estimate "$data/session.csv" --out "$data/angles.csv"
echo "Recording (with the live angles) and the offline angles are in $data"
