#!/usr/bin/env bash
# Recordings without trunk columns estimate exactly as before the trunk was added: the outputs'
# SHA-256 against tests/data/estimate-golden/SHA256SUMS (see its README).
# Usage: estimate_golden.sh ARMTRACK_CLI DATA_DIR
set -euo pipefail
cli="$1"
data="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
run() {  # run NAME INPUT [estimate options]
  local name="$1" input="$2"
  shift 2
  "$cli" estimate "$data/$input" --out "$out/$name" "$@" >/dev/null 2>"$out/$name.log" || {
    echo "estimate $input $* failed:" >&2
    cat "$out/$name.log" >&2
    exit 1
  }
}
run kinect.est.csv kinect.csv
run kinect.ukf.est.csv kinect.csv --filter ukf
run webcam_left.est.csv webcam_left.csv
run imus.B.est.csv imus.csv --method B
run imus.C.est.csv imus.csv --method C
cd "$out"
if ! sha256sum --check --strict "$data/SHA256SUMS"; then
  echo "estimates of recordings without a trunk changed (tests/data/estimate-golden/README.md)" >&2
  exit 1
fi
