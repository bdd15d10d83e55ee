#!/usr/bin/env bash
# Proves the README's quick start on a fresh Debian 12 machine: builds a minimal Debian 12
# (bookworm) root with mmdebstrap (minbase: no compiler, no X, nothing of this machine's
# packages), copies the committed tree (git archive HEAD, as a clean clone has it) into it, and
# runs the README's two commands there as a new user would: scripts/setup.sh, then
# scripts/test.sh. Not part of the test run (it downloads and installs every package, then
# builds and tests twice: about an hour on 2 cores).
#
# Usage: scripts/fresh_root.sh [ROOT_DIR]     (default /var/tmp/pineda-fresh-root; needs root)
#   KEEP_ROOT=1 keeps the root afterwards; FUZZ_SECONDS is passed on to scripts/test.sh.
# Logs: ROOT_DIR.setup.log, ROOT_DIR.test.log; the summary is printed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=${1:-/var/tmp/pineda-fresh-root}
MIRROR=${MIRROR:-http://deb.debian.org/debian}
SECURITY=${SECURITY:-http://deb.debian.org/debian-security}

if [ "$(id -u)" -ne 0 ]; then
  echo "fresh_root: needs root (chroot and mounts)" >&2
  exit 2
fi
command -v mmdebstrap >/dev/null || {
  echo "fresh_root: needs mmdebstrap (apt-get install mmdebstrap)" >&2
  exit 2
}

mounted=()
cleanup() {
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" 2>/dev/null || true; done
  if [ "${KEEP_ROOT:-0}" != 1 ]; then rm -rf "$ROOT"; fi
}
trap cleanup EXIT

rm -rf "$ROOT"
echo "== fresh_root: mmdebstrap bookworm (minbase) into $ROOT"
start=$(date +%s)
mmdebstrap --variant=minbase --aptopt='Acquire::Check-Valid-Until "false"' bookworm "$ROOT" \
  "deb $MIRROR bookworm main" "deb $MIRROR bookworm-updates main" \
  "deb $SECURITY bookworm-security main"
echo "fresh_root: root made in $(($(date +%s) - start)) s; packages: $(chroot "$ROOT" dpkg -l | grep -c '^ii')"

mkdir -p "$ROOT/root/pineda"
git archive HEAD | tar -x -C "$ROOT/root/pineda"
for m in proc sys dev dev/pts; do
  mount --bind "/$m" "$ROOT/$m"
  mounted+=("$ROOT/$m")
done

run_step() { # NAME COMMAND: run COMMAND in the root, log to ROOT.NAME.log, print its time
  local name=$1 cmd=$2 t0 rc
  t0=$(date +%s)
  set +e
  chroot "$ROOT" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 FUZZ_SECONDS="${FUZZ_SECONDS:-60}" bash -c "cd /root/pineda && $cmd" \
    >"$ROOT.$name.log" 2>&1
  rc=$?
  set -e
  echo "fresh_root: $cmd: exit $rc after $(($(date +%s) - t0)) s (log $ROOT.$name.log)"
  tail -n 5 "$ROOT.$name.log"
  return $rc
}

echo "== fresh_root: the README's quick start, command 1"
run_step setup scripts/setup.sh
echo "== fresh_root: the README's quick start, command 2"
run_step test scripts/test.sh
grep -E "tests passed|tests failed" "$ROOT.test.log" || true
echo "fresh_root: both commands passed on a fresh Debian 12 root in $(($(date +%s) - start)) s"
