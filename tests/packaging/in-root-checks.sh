#!/usr/bin/env bash
# The checks of package_install, run by mmdebstrap as a customize hook once the clean root is
# made (/proc, /sys and /dev are mounted in it then). Runs on the host; everything ArmTrack runs
# from the root's installed files, through chroot.
#   in-root-checks.sh WORKDIR SOURCE_DIR VERSION ROOT
# 1. apt installs the dependencies of WORKDIR/armtrack.deb (without Recommends), then the
#    package alone;
# 2. armtrack-cli: --version, devices (every plugin from the installed folder), a live session
#    with the virtual arm, and the clinical records (a database, a patient, a recorded session, its
#    PDF report in English and in every shipped translation: Qt's SQLite driver and the reports'
#    font come from the package's dependencies, the translations are built into the programs);
# 3. armtrack-server started as its systemd unit's ExecStart says, with the package's
#    configuration file and a certificate made here, as an ordinary user: GET /api/v1/health
#    answers 200 over HTTPS (curl on the host), then it is stopped;
# 4. armtrack --demo --lang de as an ordinary user under Xvfb, until its live screen shows
#    estimates;
# 5. apt purges the package: none of its files is left, and the root is as it was before the
#    package was installed (its dependencies stay), outside the home folders, /tmp, logs, caches
#    and dpkg's and apt's own state.
set -euo pipefail
work="$1" src="$2" version="$3" root="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ma="$(dpkg-architecture -qDEB_HOST_MULTIARCH)"
step() { echo "package_install: $*"; }
fail() {
  echo "package_install: FAIL: $*" >&2
  exit 1
}
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 "$@"; }

# What the root holds, less what running programs and apt change by design.
snapshot() {
  (cd "$root" && find . -xdev \( -path ./proc -o -path ./sys -o -path ./dev -o -path ./run \
    -o -path ./tmp -o -path ./var/tmp -o -path ./home -o -path ./root -o -path ./var/log \
    -o -path ./var/cache -o -path ./var/lib/apt -o -path ./var/lib/dpkg \) -prune -o -print |
    LC_ALL=C sort) >"$1"
}

# 1. Install: first what the package depends on (apt-get satisfy with its Depends field; the user
# who runs the application is made then too), then the package itself, alone, between two
# snapshots of the root.
in_root useradd --create-home --shell /bin/bash therapist
cp "$work/armtrack.deb" "$root/tmp/armtrack_${version}.deb"
depends="$(dpkg-deb -f "$work/armtrack.deb" Depends)"
step "apt-get satisfy the Depends field (no Recommends)"
t0=$SECONDS
in_root DEBIAN_FRONTEND=noninteractive apt-get satisfy -y -q --no-install-recommends \
  "$depends" >"$work/apt-satisfy.log" 2>&1 ||
  { tail -n 30 "$work/apt-satisfy.log" >&2; fail "apt could not install the package's dependencies"; }
step "$(grep -c '^Setting up ' "$work/apt-satisfy.log") packages installed in $((SECONDS - t0)) s"
snapshot "$work/before.list"
in_root DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
  "/tmp/armtrack_${version}.deb" >"$work/apt-install.log" 2>&1 ||
  { tail -n 30 "$work/apt-install.log" >&2; fail "apt could not install the package"; }
grep -q '^0 upgraded, 1 newly installed, 0 to remove' "$work/apt-install.log" ||
  fail "installing the package needed more than its Depends: $(grep 'newly installed' "$work/apt-install.log")"
[ "$(in_root dpkg-query -W -f='${Status} ${Version}' armtrack)" = "install ok installed $version" ] ||
  fail "dpkg does not list armtrack $version as installed"
in_root dpkg-query -L armtrack | LC_ALL=C sort >"$work/armtrack.list"
step "apt-get install ./armtrack_${version}.deb: $(wc -l <"$work/armtrack.list") paths"

# Every ELF file of the package (3 programs, the device API, 8 plugins) finds its libraries in the
# clean root.
elf_count=0
while read -r f; do
  [ -f "$root$f" ] && [ "$(head -c 4 "$root$f" | od -An -c | tr -d ' ')" = '177ELF' ] || continue
  elf_count=$((elf_count + 1))
  missing="$(in_root ldd "$f" | grep 'not found' || true)"
  [ -z "$missing" ] || fail "$f: $missing"
done <"$work/armtrack.list"
[ "$elf_count" -eq 12 ] || fail "expected 12 ELF files installed, found $elf_count"
step "ldd: the $elf_count ELF files find all their libraries in the root"

# 2. The command-line tool.
out="$(in_root armtrack-cli --version)"
[ "$out" = "armtrack-cli $version" ] || fail "armtrack-cli --version said '$out'"
out="$(in_root armtrack --version)"
[ "$out" = "armtrack $version" ] || fail "armtrack --version said '$out'"
out="$(in_root armtrack-server --version)"
[ "$out" = "armtrack-server $version" ] || fail "armtrack-server --version said '$out'"

devices="$(in_root armtrack-cli devices 2>&1)"
grep -q '^refused' <<<"$devices" && fail "plugins refused: $(grep '^refused' <<<"$devices")"
for plugin in kinect line-imu ngimu replay shimmer3 skeleton-udp virtual-arm webcam; do
  grep -q "^$plugin: " <<<"$devices" || fail "armtrack-cli devices does not list $plugin"
  grep -q "(/usr/lib/$ma/armtrack/plugins/armtrack-$plugin.so)" <<<"$devices" ||
    fail "$plugin is not loaded from /usr/lib/$ma/armtrack/plugins"
done
step "armtrack-cli devices: 8 plugins from /usr/lib/$ma/armtrack/plugins"

live="$(in_root timeout 60 armtrack-cli live --device virtual-arm --duration 2 --stats 2>&1)" ||
  fail "armtrack-cli live failed: $live"
rows="$(sed -n 's/.*rows \([0-9]*\)  estimates \([0-9]*\).*lost \([0-9]*\)$/\1 \2 \3/p' <<<"$live" | tail -n 1)"
read -r nrows nest nlost <<<"${rows:-0 0 -1}"
[ "$nrows" -gt 1000 ] && [ "$nest" -gt 1000 ] && [ "$nlost" -eq 0 ] ||
  fail "the live session with the virtual arm: $live"
step "armtrack-cli live: $nrows rows, $nest estimates, $nlost lost in 2 s"

records() { in_root ARMTRACK_PASSWORD=install-test timeout 120 armtrack-cli "$@"; }
records db init --db /root/clinic.db --admin boss >/dev/null 2>&1 || fail "db init failed"
records patient add --db /root/clinic.db --user boss --code P01 --name "Ada Example" \
  --birth 1950-01-02 --sex f --side right >/dev/null 2>&1 || fail "patient add failed"
records record --device virtual-arm --duration 3 --db /root/clinic.db --user boss \
  --patient P01 >"$work/record.out" 2>"$work/record.err" ||
  fail "record --db failed: $(cat "$work/record.err")"
session="$(sed -n 's/^session \([0-9]*\)$/\1/p' "$work/record.out")"
[ -n "$session" ] || fail "record --db printed no session id: $(cat "$work/record.out")"
records report "$session" --pdf /root/session.pdf --db /root/clinic.db --user boss >/dev/null 2>&1 ||
  fail "report of session $session failed"
[ "$(head -c 5 "$root/root/session.pdf")" = "%PDF-" ] || fail "the report is not a PDF"
step "armtrack-cli: records on SQLite, session $session recorded and its PDF report written" \
  "($(stat -c %s "$root/root/session.pdf") bytes)"

# The translations are built into the programs (app/i18n): the installed CLI writes the report in
# every shipped language, with the title translations/armtrack_<lang>.ts gives (the PDFs are read
# on the host with pdftotext); the English report above has the source text.
pdf_words() { pdftotext -q "$1" - | tr -s '[:space:]' ' '; }
title_en="Session report"
grep -qF "$title_en" <<<"$(pdf_words "$root/root/session.pdf")" ||
  fail "the English report has no '$title_en'"
languages=()
for ts in "$src"/translations/armtrack_*.ts; do
  lang="$(basename "${ts%.ts}")"
  lang="${lang#armtrack_}"
  [ "$lang" = en ] && continue # English: the plural forms only
  title="$(/usr/bin/python3 "$here/ts-translation.py" "$ts" armtrack::reports "$title_en")" ||
    fail "$(basename "$ts") has no translation of '$title_en'"
  records report "$session" --lang "$lang" --pdf "/root/session-$lang.pdf" --db /root/clinic.db \
    --user boss >/dev/null 2>&1 || fail "report --lang $lang failed"
  words="$(pdf_words "$root/root/session-$lang.pdf")"
  grep -qF "$title" <<<"$words" || fail "the report in '$lang' has no '$title': ${words:0:300}"
  grep -qF "$title_en" <<<"$words" && fail "the report in '$lang' still says '$title_en'"
  languages+=("$lang '$title'")
done
[ ${#languages[@]} -gt 0 ] || fail "no translations/armtrack_<lang>.ts in $src"
step "armtrack-cli report --lang: ${languages[*]}"

# 3. The sync service as its systemd unit starts it (systemd does not run in the root): the unit's
# ExecStart, with its credentials folder (%d) holding a certificate and key made here, reads the
# package's /etc/armtrack/server.conf; the records (a SQLite file) and the port are given on the
# command line, which wins over the file. It runs as an ordinary user, as the unit's own user
# would; curl on the host (the root shares its network) checks the health answer over HTTPS.
t0=$SECONDS
unit="$root/lib/systemd/system/armtrack-server.service"
exec_start="$(sed -n 's/^ExecStart=//p' "$unit")"
[ -n "$exec_start" ] || fail "armtrack-server.service has no ExecStart"
cred=/tmp/armtrack-server-credentials
mkdir -p "$root$cred"
openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:P-256 -nodes -days 1 -subj /CN=localhost \
  -addext subjectAltName=DNS:localhost -keyout "$root$cred/server.key" \
  -out "$root$cred/server.crt" >"$work/openssl.log" 2>&1 || fail "openssl: $(cat "$work/openssl.log")"
records db init --db /tmp/server-records.db --admin boss >/dev/null 2>&1 || fail "db init for the server failed"
in_root chown -R therapist:therapist "$cred" /tmp/server-records.db
port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
# shellcheck disable=SC2086 # the unit's command line, split into words as systemd does
chroot --userspec=therapist:therapist "$root" /usr/bin/env -i PATH=/usr/bin:/bin \
  HOME=/home/therapist LANG=C.UTF-8 ${exec_start//%d/$cred} --db /tmp/server-records.db \
  --port "$port" --listen 127.0.0.1 >"$work/server.out" 2>"$work/server.log" &
server_pid=$!
for _ in $(seq 300); do
  grep -q 'listening on' "$work/server.out" && break
  kill -0 "$server_pid" 2>/dev/null || break
  sleep 0.1
done
health="$(curl -sS --max-time 30 --cacert "$root$cred/server.crt" \
  --resolve "localhost:$port:127.0.0.1" -w ' %{http_code}' "https://localhost:$port/api/v1/health" 2>&1 ||
  true)"
kill -TERM "$server_pid" 2>/dev/null || true
wait "$server_pid" 2>/dev/null || true
rm -rf "${root:?}$cred" "$root"/tmp/server-records.db*
[ "${health##* }" = 200 ] && grep -q '"status":"ok"' <<<"$health" ||
  fail "GET /api/v1/health of the installed armtrack-server: '$health'; its log: $(cat "$work/server.out" "$work/server.log")"
step "armtrack-server (the unit's command, port $port): $(head -n 1 "$work/server.out"); health:" \
  "$health ($((SECONDS - t0)) s)"

# 4. The application, as an ordinary user, on a virtual display of the host's: the X server's
# abstract socket is reachable from the chroot, which shares the host's network namespace.
in_root install -d -m 0700 -o therapist -g therapist /tmp/runtime-therapist
exec 3< <(Xvfb -displayfd 4 -screen 0 1280x800x24 -nolisten tcp 4>&1 >/dev/null 2>"$work/xvfb.log")
xvfb_pid=$!
trap 'kill "$xvfb_pid" 2>/dev/null || true' EXIT
read -r -t 30 display <&3 || fail "Xvfb did not start: $(cat "$work/xvfb.log")"
step "armtrack --demo on display :$display until the live screen shows estimates"
t0=$SECONDS
set +e
chroot --userspec=therapist:therapist "$root" /usr/bin/env -i PATH=/usr/bin:/bin \
  HOME=/home/therapist USER=therapist LANG=C.UTF-8 DISPLAY=":$display" \
  XDG_RUNTIME_DIR=/tmp/runtime-therapist \
  timeout 300 armtrack --demo --lang de --quit-when-live --quit-after 240 \
  --screenshot /home/therapist/installed-demo.png >"$work/armtrack.log" 2>&1
code=$?
set -e
kill "$xvfb_pid" 2>/dev/null || true
[ "$code" -eq 0 ] || { cat "$work/armtrack.log" >&2; fail "armtrack --demo exited with $code"; }
running="$(grep 'the live session is running' "$work/armtrack.log" || true)"
[ -n "$running" ] || { cat "$work/armtrack.log" >&2; fail "armtrack never reported its live session"; }
grep -q 'refused plugin' "$work/armtrack.log" && fail "$(grep 'refused plugin' "$work/armtrack.log")"
cp "$root/home/therapist/installed-demo.png" "$work/installed-demo.png" ||
  fail "armtrack saved no screenshot"
step "armtrack: ${running#armtrack: } ($((SECONDS - t0)) s after start; its window:" \
  "$work/installed-demo.png)"

# 5. Purge: nothing of the package left, nothing else changed.
in_root DEBIAN_FRONTEND=noninteractive apt-get purge -y -q armtrack >"$work/apt-purge.log" 2>&1 ||
  { tail -n 30 "$work/apt-purge.log" >&2; fail "apt could not purge the package"; }
in_root dpkg-query -W armtrack >/dev/null 2>&1 && fail "dpkg still knows armtrack after the purge"
snapshot "$work/after.list"
left=()
while read -r path; do
  [ "$path" = "/." ] && continue
  [ -e "$root$path" ] || [ -L "$root$path" ] || continue
  # A folder another installed package owns too (/usr/bin, /usr/share/man/man1, ...) stays.
  [ -d "$root$path" ] && in_root dpkg-query -S "$path" >/dev/null 2>&1 && continue
  left+=("$path")
done <"$work/armtrack.list"
[ ${#left[@]} -eq 0 ] || fail "left behind after the purge: ${left[*]}"
# Whatever the maintainer scripts or the programs (run as root) made outside the home folders.
changed="$(LC_ALL=C diff "$work/before.list" "$work/after.list" || true)"
[ -z "$changed" ] || fail "the root differs from before the installation (< before, > after): $changed"
step "purged: the package's $(wc -l <"$work/armtrack.list") paths gone, the root as before it"
