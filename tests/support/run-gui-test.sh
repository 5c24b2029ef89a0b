#!/bin/sh
# Runs a GUI test program under a virtual X server with Mesa's software OpenGL (Qt's offscreen
# platform cannot host the VTK view). Used by armtrack_add_gui_test (tests/CMakeLists.txt).
if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "run-gui-test: xvfb-run not found; install xvfb and xauth (packaging/deps-debian12.sh)" >&2
  exit 1
fi
export QT_QPA_PLATFORM=xcb
export LIBGL_ALWAYS_SOFTWARE=1
# -a picks a free display number; the screen is the size the screenshots are taken at
# (ARMTRACK_XVFB_SCREEN, e.g. 1024x600; default 1280x800).
exec xvfb-run -a -s "-screen 0 ${ARMTRACK_XVFB_SCREEN:-1280x800}x24 -nolisten tcp" "$@"
