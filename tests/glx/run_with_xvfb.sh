#!/usr/bin/env bash
# Runs a command against a private Xvfb: Xvfb picks a free display number itself (-displayfd),
# the command gets it in DISPLAY, and the server is stopped afterwards whatever happens.
# -noreset: a server that resets when its last client leaves refuses connections meanwhile,
# and each test opens its own connection.
# Usage: run_with_xvfb.sh XVFB_PATH COMMAND [ARGS...]
set -u
xvfb=$1
shift
fifo_dir=$(mktemp -d)
trap 'kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null; rm -rf "$fifo_dir"' EXIT
"$xvfb" -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3>"$fifo_dir/display" 2>"$fifo_dir/log" &
xvfb_pid=$!
for _ in $(seq 100); do
  [ -s "$fifo_dir/display" ] && break
  kill -0 "$xvfb_pid" 2>/dev/null || break
  sleep 0.1
done
if [ ! -s "$fifo_dir/display" ]; then
  echo "run_with_xvfb: Xvfb did not start:" >&2
  cat "$fifo_dir/log" >&2
  exit 1
fi
export DISPLAY=":$(head -n1 "$fifo_dir/display")"
"$@"
