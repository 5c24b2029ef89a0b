#!/usr/bin/env bash
# package_install: installs the .deb into a clean Debian 12 root and runs ArmTrack from the
# installed files (docs/packaging.md).
#   install-test.sh DEB WORKDIR SOURCE_DIR
# mmdebstrap makes a minimal bookworm root (the minbase variant: essential and required packages
# and apt) in WORKDIR/root from the machine's Debian sources, taking packages the machine's apt
# already downloaded from its cache (hard links) and the rest from the mirror. Inside it, apt
# installs the package with its dependencies (Depends only, no Recommends), and
# in-root-checks.sh runs the programs and purges the package. Nothing is kept outside WORKDIR;
# the root is deleted after a pass and kept after a failure, to look at.
# Needs root (chroot, mounts), mmdebstrap, Xvfb, pdftotext, openssl and curl; exits 77 (skipped) when not root,
# unless CI is set.
set -euo pipefail
deb="$(realpath "$1")" work="$2" src="$(realpath "$3")"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
say() { echo "package_install: $*"; }

# Without root the test cannot run at all: a developer's unprivileged run skips it (status 77,
# shown by ctest as skipped), CI (CI set, as .ci/run runs) fails instead, so the package is never
# left untested unnoticed. A missing tool fails everywhere.
if [ "$(id -u)" -ne 0 ]; then
  if [ -n "${CI:-}" ]; then
    say "FAIL: needs root (chroot and mounts), and CI=$CI: CI must run it" >&2
    exit 1
  fi
  say "SKIPPED: needs root (chroot and mounts); run the test command as root"
  exit 77
fi
for tool in mmdebstrap Xvfb chroot findmnt pdftotext openssl curl /usr/bin/python3; do
  command -v "$tool" >/dev/null ||
    { say "FAIL: $tool not found (packaging/deps-debian12.sh installs it)" >&2; exit 1; }
done
[ -f "$deb" ] || { say "FAIL: no package at $deb" >&2; exit 1; }

mkdir -p "$work"
work="$(realpath "$work")"
root="$work/root"
# A root left by an earlier run: never delete through a mount that is still there.
if [ -e "$root" ]; then
  if findmnt -rn -o TARGET | grep -q "^$root\(/\|$\)"; then
    say "FAIL: something is still mounted under $root; unmount it first" >&2
    exit 1
  fi
  rm -rf --one-file-system "$root"
fi

# The machine's Debian sources (deb822 or one-line), else the default mirror.
sources=()
for f in /etc/apt/sources.list.d/debian.sources /etc/apt/sources.list; do
  if [ -s "$f" ] && grep -q 'debian' "$f"; then
    sources=("$f")
    break
  fi
done
cache_hook='mkdir -p "$1/var/cache/apt/archives"'
if compgen -G '/var/cache/apt/archives/*.deb' >/dev/null; then
  # Hard links when the cache is on the same file system, else copies.
  cache_hook+=' && { cp -l /var/cache/apt/archives/*.deb "$1/var/cache/apt/archives/" 2>/dev/null ||
    cp /var/cache/apt/archives/*.deb "$1/var/cache/apt/archives/"; }'
fi
hook_dir=()
[ -d /usr/share/mmdebstrap/hooks/eatmydata ] && command -v eatmydata >/dev/null &&
  hook_dir=(--hook-dir=/usr/share/mmdebstrap/hooks/eatmydata)

cp "$deb" "$work/armtrack.deb"
checks="$(printf '%q %q %q %q' "$here/in-root-checks.sh" "$work" "$src" "$(dpkg-deb -f "$deb" Version)")"
started=$SECONDS
say "making a clean Debian 12 root in $root with mmdebstrap; the checks run inside it"
# The checks' hook comes before eatmydata's customize hook, which removes it again: dpkg inside
# the checks runs without fsync too (a third of the time).
if mmdebstrap --variant=minbase --mode=root --format=directory \
    --setup-hook="$cache_hook" \
    --customize-hook="$checks \"\$1\"" "${hook_dir[@]}" \
    bookworm "$root" "${sources[@]}"; then
  say "ok in $((SECONDS - started)) s; deleting the root"
  rm -rf --one-file-system "$root" "$work/armtrack.deb"
else
  say "FAILED after $((SECONDS - started)) s; the root is kept in $root" >&2
  exit 1
fi
