#!/usr/bin/env bash
# A demo in window mode on Pineda: the window's title must show the frame rate and Pineda as
# the renderer ("NAME - X FPS - Pineda ..."), a left click at (X, Y) goes to the demo, and ESC
# must end the program with status 0. With EXPECT, the demo's output must contain that text
# (the picking demo prints what the click picked).
# Usage: window_mode.sh DEMO X_ESCAPE LIB_DIR NAME X Y [EXPECT]
# (under tests/glx/run_with_xvfb.sh)
set -u
demo=$1 x_escape=$2 lib_dir=$3 name=$4 click_x=$5 click_y=$6 expect=${7:-}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
LD_LIBRARY_PATH="$lib_dir" "$demo" --size 320x240 >"$log" 2>&1 &
pid=$!
# The first title is the bare name; the frame rate and the renderer replace it after half a
# second.
if ! "$x_escape" "$name - " 20 "$pid" "$click_x" "$click_y" | grep -E "\"$name - [0-9.]+ FPS - Pineda"; then
  kill "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  cat "$log"
  echo "window_mode: no window title with the frame rate and Pineda" >&2
  exit 1
fi
for _ in $(seq 100); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$pid" 2>/dev/null; then
  kill "$pid"
  wait "$pid" 2>/dev/null
  echo "window_mode: $name did not quit on ESC" >&2
  exit 1
fi
wait "$pid"
rc=$?
cat "$log"
if [ $rc -ne 0 ]; then
  echo "window_mode: $name exited with status $rc" >&2
  exit $rc
fi
if [ -n "$expect" ] && ! grep -qF "$expect" "$log"; then
  echo "window_mode: $name did not print \"$expect\"" >&2
  exit 1
fi
