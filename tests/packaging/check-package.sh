#!/usr/bin/env bash
# package_contents: what the .deb holds, checked without installing it. The files are where
# docs/packaging.md says; the desktop entry and the AppStream metadata validate; the manual pages
# render without warnings; the licence is in Debian's machine-readable format; every program,
# library and plugin finds its libraries from the installed location (relative RUNPATHs, nothing
# pointing into the build tree) and none links Qt 5; the control file names the runtime packages
# that are loaded without being linked. The translations are built into the programs (app/i18n);
# package_install checks them by running the installed CLI.
#   check-package.sh DEB WORKDIR
set -euo pipefail
deb="$1" work="$(realpath -m "$2")"
status=0
fail() {
  echo "package_contents: FAIL: $*" >&2
  status=1
}
[ -f "$deb" ] || { echo "package_contents: FAIL: no package at $deb" >&2; exit 1; }
# The checkers: a missing one is a failure, never a skip (packaging/deps-debian12.sh installs them).
for tool in dpkg-deb dpkg-architecture dpkg-parsechangelog lintian desktop-file-validate appstreamcli groff col readelf ldd systemd-analyze \
  /usr/bin/python3; do
  command -v "$tool" >/dev/null ||
    { echo "package_contents: FAIL: $tool not found (packaging/deps-debian12.sh installs it)" >&2; exit 1; }
done
/usr/bin/python3 -c 'import debian.copyright' 2>/dev/null ||
  { echo "package_contents: FAIL: python3-debian not installed (packaging/deps-debian12.sh)" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
root="$work/root"
dpkg-deb -x "$deb" "$root"
dpkg-deb -e "$deb" "$work/DEBIAN"
ma="$(dpkg-architecture -qDEB_HOST_MULTIARCH)"
version="$(dpkg-deb -f "$deb" Version)"
app=org.armtrack.ArmTrack
echo "package_contents: $(basename "$deb"): version $version, $(dpkg-deb -c "$deb" | wc -l) entries"

# Where everything goes.
expected=(
  /usr/bin/armtrack /usr/bin/armtrack-cli /usr/bin/armtrack-server
  "/usr/lib/$ma/armtrack/libarmtrack_device_api.so"
  /usr/share/applications/$app.desktop /usr/share/metainfo/$app.metainfo.xml
  /usr/share/icons/hicolor/scalable/apps/$app.svg
  /usr/share/man/man1/armtrack-cli.1.gz /usr/share/man/man1/armtrack.1.gz
  /usr/share/man/man1/armtrack-server.1.gz
  /lib/systemd/system/armtrack-server.service /etc/armtrack/server.conf
  /usr/share/doc/armtrack/copyright /usr/share/doc/armtrack/NOTICE
  /usr/share/doc/armtrack/changelog.gz
)
for size in 16 22 24 32 48 64 128 256 512; do
  expected+=("/usr/share/icons/hicolor/${size}x${size}/apps/$app.png")
done
for plugin in kinect line-imu ngimu replay shimmer3 skeleton-udp virtual-arm webcam; do
  expected+=("/usr/lib/$ma/armtrack/plugins/armtrack-$plugin.so")
done
for f in "${expected[@]}"; do
  [ -f "$root$f" ] || fail "$f is not in the package"
done
outside="$(cd "$root" && find . -mindepth 1 -maxdepth 1 ! -name usr ! -name etc ! -name lib)"
[ -z "$outside" ] || fail "files outside /usr, /etc and /lib: $outside"
# Outside /usr: armtrack-server's systemd unit and its configuration, a conffile (dpkg keeps a
# clinic's edits), and nothing else.
for top in etc lib; do
  extra="$(cd "$root" && find "$top" -type f ! -path etc/armtrack/server.conf \
    ! -path lib/systemd/system/armtrack-server.service)"
  [ -z "$extra" ] || fail "unexpected files in /$top: $extra"
done
[ "$(cat "$work/DEBIAN/conffiles" 2>/dev/null)" = /etc/armtrack/server.conf ] ||
  fail "conffiles is not /etc/armtrack/server.conf: $(cat "$work/DEBIAN/conffiles" 2>&1)"

# The unit: valid for systemd, started as the package's armtrack-server with the configuration
# file, a user of its own, and only once a certificate is in place (the package brings none).
unit="$root/lib/systemd/system/armtrack-server.service"
if [ -f "$unit" ]; then
  # The program is in the unpacked tree, not in /usr/bin: that one complaint is expected.
  verify="$(systemd-analyze verify --man=no "$unit" 2>&1 |
    grep -v '^armtrack-server.service: Command /usr/bin/armtrack-server is not executable' || true)"
  [ -z "$verify" ] || fail "systemd-analyze verify: $verify"
  for line in '^ExecStart=/usr/bin/armtrack-server --config /etc/armtrack/server.conf ' \
    '^DynamicUser=yes$' '^ConditionPathExists=/etc/armtrack/server.crt$' \
    '^ConditionPathExists=/etc/armtrack/server.key$' '^ProtectSystem=strict$' '^PrivateTmp=yes$'; do
    grep -q "$line" "$unit" || fail "armtrack-server.service has no line matching '$line'"
  done
fi

# Icons: PNGs of the size their folder says (the PNG header's width and height).
for png in "$root"/usr/share/icons/hicolor/*x*/apps/$app.png; do
  size="$(basename "$(dirname "$(dirname "$png")")")"
  read -r w h < <(od -An -tu1 -j16 -N8 "$png" |
    awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}')
  [ "${w}x${h}" = "$size" ] || fail "$png is ${w}x${h}"
done

# The desktop entry and the AppStream metadata.
desktop="$root/usr/share/applications/$app.desktop"
metainfo="$root/usr/share/metainfo/$app.metainfo.xml"
desktop-file-validate "$desktop" || fail "desktop-file-validate refused $app.desktop"
appstreamcli validate --no-net --strict "$metainfo" || fail "appstreamcli refused the metainfo"
exec_line="$(sed -n 's/^Exec=//p' "$desktop")"
[ -x "$root/usr/bin/${exec_line%% *}" ] || fail "the desktop entry starts '$exec_line', not in /usr/bin"
[ "$(sed -n 's/^Icon=//p' "$desktop")" = "$app" ] || fail "the desktop entry's icon is not $app"
grep -q "<launchable type=\"desktop-id\">$app.desktop</launchable>" "$metainfo" ||
  fail "the metainfo does not launch $app.desktop"
grep -q "<release version=\"$version\"" "$metainfo" || fail "the metainfo has no release $version"

# Manual pages: groff's warnings are errors; the version is filled in.
for page in armtrack-cli armtrack armtrack-server; do
  gz="$root/usr/share/man/man1/$page.1.gz"
  [ -f "$gz" ] || continue
  warnings="$(zcat "$gz" | groff -man -ww -z 2>&1)"
  [ -z "$warnings" ] || fail "$page.1: $warnings"
  text="$(zcat "$gz" | groff -man -Tutf8 2>/dev/null | col -b)"
  grep -q "ArmTrack $version" <<<"$text" || fail "$page.1 does not name version $version"
  grep -q '^NAME' <<<"$text" || fail "$page.1 has no NAME section"
done

# The licence file in Debian's machine-readable format (python3-debian's strict parser, with
# Debian's own Python: another python3 may come first on PATH).
/usr/bin/python3 - "$root/usr/share/doc/armtrack/copyright" <<'EOF' || fail "copyright is not machine-readable"
import sys
from debian.copyright import Copyright
with open(sys.argv[1], encoding="utf-8") as f:
    c = Copyright(f, strict=True)
files = c.find_files_paragraph("usr/bin/armtrack")
assert files is not None and files.license.synopsis == "GPL-3+", "no GPL-3+ paragraph for *"
assert c.header.upstream_name == "ArmTrack"
EOF

# Debian's own checker of packages: no error and no warning (its notes, e.g. hardening flags the
# project's build does not set, are not failures).
lintian_out="$(lintian --fail-on error,warning "$deb" 2>&1)" ||
  fail "lintian: $(grep -v 'root privileges' <<<"$lintian_out")"

# The changelog of a native package: its newest entry is this version, of the metainfo's release
# date.
changelog="$work/changelog"
zcat "$root/usr/share/doc/armtrack/changelog.gz" >"$changelog" 2>/dev/null ||
  fail "changelog.gz is missing or not gzip-compressed"
if [ -s "$changelog" ]; then
  [ "$(dpkg-parsechangelog -l "$changelog" -S Version 2>&1)" = "$version" ] ||
    fail "the changelog's newest entry is not $version: $(head -n 1 "$changelog")"
  released="$(date -u -d "$(dpkg-parsechangelog -l "$changelog" -S Date 2>/dev/null)" +%F 2>&1)"
  grep -q "<release version=\"$version\" date=\"$released\"" "$metainfo" ||
    fail "the changelog dates $version $released, the metainfo: $(grep -o '<release [^>]*>' "$metainfo")"
fi

# ELF files: relative RUNPATHs only, every library found from the unpacked tree, no Qt 5.
elf_count=0
while IFS= read -r -d '' f; do
  [ "$(head -c 4 "$f" | od -An -c | tr -d ' ')" = '177ELF' ] || continue
  elf_count=$((elf_count + 1))
  rel="${f#"$root"}"
  runpath="$(readelf -d "$f" | sed -n 's/.*(RUNPATH).*\[\(.*\)\]/\1/p; s/.*(RPATH).*\[\(.*\)\]/\1/p')"
  case "$runpath" in
    "" | '$ORIGIN'*) ;;
    *) fail "$rel has RUNPATH '$runpath' (not relative to the install)" ;;
  esac
  deps="$(ldd "$f" 2>&1)"
  grep -q 'not found' <<<"$deps" && fail "$rel: $(grep 'not found' <<<"$deps" | tr -s ' \t' ' ')"
  grep -q 'libQt5' <<<"$deps" && fail "$rel links Qt 5"
  if grep -q libarmtrack_device_api <<<"$deps" &&
    ! grep -q "libarmtrack_device_api.so => $root/usr/lib/$ma/armtrack/" <<<"$(sed 's|/[^/]*/\.\./|/|g' <<<"$deps")"; then
    fail "$rel does not take libarmtrack_device_api from the package: $(grep device_api <<<"$deps")"
  fi
done < <(find "$root" -type f -print0)
[ "$elf_count" -eq 12 ] || fail "expected 12 ELF files (3 programs, 1 library, 8 plugins), found $elf_count"

# Dependencies: dpkg-shlibdeps' libraries and what is loaded without being linked.
depends="$(dpkg-deb -f "$deb" Depends)"
for p in libqt6core6 libqt6widgets6 libqt6charts6 libqt6multimedia6 libvtk9.1 libopencv-core406 \
  libc6 libqt6sql6-sqlite libqt6sql6-psql libgl1-mesa-dri libglx-mesa0 fonts-dejavu-core; do
  grep -Eq "(^|, )$p( |,|$)" <<<"$depends" || fail "Depends lacks $p: $depends"
done
grep -q 'libqt5\|qt5' <<<"$depends" && fail "Depends names Qt 5: $depends"

if [ "$status" -eq 0 ]; then
  echo "package_contents: ok: ${#expected[@]} expected files, $elf_count ELF files, desktop entry," \
    "AppStream metadata, manual pages and copyright valid"
fi
exit "$status"
