#!/usr/bin/env bash
# Installs the Debian 12 packages ArmTrack needs to build, run and test. Idempotent: skips apt
# when everything is already installed. Needs root (or sudo).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev nlohmann-json3-dev libopencv-dev libopencv-contrib-dev libceres-dev
  qt6-base-dev qt6-serialport-dev libqt6sql6-sqlite libfreenect-dev libfreenect-bin
  qt6-tools-dev qt6-l10n-tools qt6-translations-l10n libxcb1-dev
  libzstd-dev libsodium-dev libpq-dev
  # armtrack-server: Qt Network's TLS (its OpenSSL backend comes with libqt6network6, libssl3);
  # openssl makes the sync tests' self-signed certificates
  openssl
  fonts-dejavu-core fonts-wqy-microhei poppler-utils
  libqt6sql6-psql postgresql
  libgtest-dev googletest libbenchmark-dev
  qt6-charts-dev qt6-multimedia-dev libqt6opengl6-dev libvtk9-dev
  xvfb xauth libgl1-mesa-dri libglx-mesa0
  clang libclang-rt-14-dev
  # lld links the test programs (tests/CMakeLists.txt), several times faster than GNU ld
  lld
  # the package (docs/packaging.md): icons, manual pages, validators, the clean-root install test
  librsvg2-bin groff-base desktop-file-utils appstream python3-debian lintian mmdebstrap eatmydata
  # armtrack-server's unit checked (systemd-analyze) and its health asked over HTTPS (curl)
  systemd curl
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
  else
    echo "deps: missing packages (${missing[*]}) and not root; run as root or install sudo" >&2
    exit 1
  fi
fi
echo "deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
