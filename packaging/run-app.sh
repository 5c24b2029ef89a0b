#!/usr/bin/env bash
# Sets up a Debian 12 machine, builds ArmTrack and starts the application in demo mode: demo
# records (patients, a protocol, six weeks of sessions), signed in as a demo therapist, and a
# live session with the virtual arm (both IMUs, a Kinect and a webcam, simulated in real time).
# Without a display it says so and runs the demo under a virtual one (xvfb-run) for a while,
# saving what the window showed as a picture.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ARMTRACK_BUILD_DIR:-$root/build}"

bash "$root/packaging/deps-debian12.sh"
# The test script's configuration (packaging/configure-build.sh); BUILD_TESTING is left as the
# folder has it, so the app after the tests, or the tests after the app, rebuild nothing shared.
bash "$root/packaging/configure-build.sh" "$root" "$build"
cmake --build "$build" --parallel "$(nproc)" --target armtrack armtrack-cli \
  armtrack_plugin_virtual-arm armtrack_plugin_replay

app="$build/app/armtrack"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$app" --demo "$@"
fi
shot="${XDG_DATA_HOME:-$HOME/.local/share}/ArmTrack/ArmTrack/demo/demo-window.png"
mkdir -p "$(dirname "$shot")"
echo "run-app: there is no display (DISPLAY is not set), so the demo runs under a virtual one"
echo "run-app: (xvfb-run) for 30 s; what its window showed is saved as $shot"
echo "run-app: on a desktop, run: $app --demo"
xvfb-run -a -s '-screen 0 1280x800x24' "$app" --demo --quit-after 30 --screenshot "$shot" "$@"
echo "run-app: the demo window at 30 s: $shot"
