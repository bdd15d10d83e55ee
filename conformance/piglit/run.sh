#!/usr/bin/env bash
# Runs a piglit list (from Debian's piglit package) against Pineda's libGL.so.1 and, for
# reference, against Mesa llvmpipe limited to the same GL version, under one private Xvfb. Not
# part of the test run (scripts/test.sh): it takes minutes (the GLSL lists, tens of minutes).
#
# Usage: conformance/piglit/run.sh [--list gl1x|glsl-shader|glsl-parser|FILE] [--build DIR]
#          [--out DIR] [--filter REGEX] [--no-mesa | --no-pineda | --mesa-passes] [--jobs N]
#          [--expect FILE] [--check-only]
# Lists (beside this script): gl1x-tests.txt (the default; Mesa at GL 1.5 with 2003's
# extensions, expectations.txt), glsl-shader-tests.txt and glsl-parser-tests.txt (written by
# make_glsl_lists.py; Mesa at GL 2.1, expectations-glsl.txt). A line is `COMMAND` (the test is
# named by its first word) or `NAME<TAB>COMMAND`; the command runs in piglit's root with its
# binary from bin/.
# Writes <out>/results.tsv (test, pineda result, mesa result, seconds) and <out>/logs/, prints
# each test and the totals, and exits non-zero when a test that passes on Mesa does not pass on
# Pineda without being listed in the expectations, or when a listed test passes (a stale entry).
# --no-pineda runs Mesa only (a baseline; no libGL.so.1 needed): results.tsv then has "-" for
# Pineda, the seconds are Mesa's, and no expectation is checked. --mesa-passes is for a list of
# tests known to pass on Mesa (glsl-sample-tests.txt, the ctest test piglit.glsl_sample): Mesa is
# not run, and the expectations are checked as if it had passed each test. --check-only runs
# nothing: it checks <out>/results.tsv and <out>/logs as an earlier run left them (or as put
# together from a Mesa-only and a Pineda-only run).
# A test Pineda skips because it needs an extension Pineda does not advertise (piglit's log says
# "Test requires GL_..." or "unsupported extension GL_...") is reported as such, not as a failure:
# Mesa at GL 2.1 keeps its later extensions, and their tests say nothing about Pineda's GL 2.1.
set -euo pipefail
cd "$(dirname "$0")/../.."

BUILD=build
OUT=piglit-out
FILTER=.
MESA=1
PINEDA=1
CHECK_ONLY=0
JOBS=2
LIST_NAME=gl1x
EXPECT=""
while [ $# -gt 0 ]; do
  case "$1" in
    --list) LIST_NAME=$2; shift 2 ;;
    --expect) EXPECT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --filter) FILTER=$2; shift 2 ;;
    --no-mesa) MESA=0; shift ;;
    --no-pineda) PINEDA=0; shift ;;
    --mesa-passes) MESA=assumed; shift ;;
    --check-only) CHECK_ONLY=1; shift ;;
    --jobs) JOBS=$2; shift 2 ;;
    -h|--help) sed -n 2,28p "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

PIGLIT=/usr/lib/x86_64-linux-gnu/piglit
BIN=$PIGLIT/bin
case "$LIST_NAME" in
  gl1x)
    LIST=conformance/piglit/gl1x-tests.txt
    # GL 1.5, as the list was chosen for (LIST.md).
    MESA_ENV="MESA_GL_VERSION_OVERRIDE=1.5 MESA_EXTENSION_MAX_YEAR=2003"
    EXPECT=${EXPECT:-conformance/piglit/expectations.txt} ;;
  glsl-shader | glsl-parser | glsl-sample)
    LIST=conformance/piglit/$LIST_NAME-tests.txt
    # GL 2.1, Pineda's version; Mesa 22.3 crashes when its GLSL version is overridden too.
    MESA_ENV="MESA_GL_VERSION_OVERRIDE=2.1"
    EXPECT=${EXPECT:-conformance/piglit/expectations-glsl.txt} ;;
  *)
    LIST=$LIST_NAME
    MESA_ENV=${MESA_ENV:-}
    EXPECT=${EXPECT:-/dev/null} ;;
esac
if [ ! -d "$BIN" ]; then
  echo "run.sh: $BIN is missing; install Debian's piglit package (scripts/deps.sh does)" >&2
  exit 2
fi
if [ "$MESA" = 0 ] && [ "$PINEDA" = 0 ]; then
  echo "run.sh: --no-mesa and --no-pineda leave nothing to run" >&2
  exit 2
fi
LIB=""
if [ "$PINEDA" = 1 ] && [ "$CHECK_ONLY" = 0 ]; then
  if [ ! -e "$BUILD/lib/libGL.so.1" ]; then
    echo "run.sh: $BUILD/lib/libGL.so.1 is missing; build the 'pineda' target first" >&2
    exit 2
  fi
  LIB=$(cd "$BUILD/lib" && pwd)
fi

if [ "$CHECK_ONLY" = 0 ]; then
  rm -rf "$OUT"
  mkdir -p "$OUT/logs"
fi

# The test's name and command of a list line (`COMMAND`, or `NAME<TAB>COMMAND`).
line_name() { if [[ $1 == *$'\t'* ]]; then echo "${1%%$'\t'*}"; else echo "${1%% *}"; fi; }
line_command() { echo "${1#*$'\t'}"; }
export -f line_name line_command

# One test, one implementation: prints the piglit result word (pass, fail, skip, warn, crash,
# timeout).
run_one() {
  local impl=$1 name log status result
  name=$(line_name "$2")
  local line
  line=$(line_command "$2")
  log="$OUT/logs/$name.$impl.log"
  # GLX for every test: piglit picks waffle's X11/EGL platform for tests that also support GL ES
  # (arb_point_sprite-checkerboard), and the EGL context it makes current is Mesa's, not ours:
  # our libGL.so.1 then has no current context and piglit crashes on a null GL_VERSION.
  local -a env_args=(PIGLIT_PLATFORM=glx)
  if [ "$impl" = pineda ]; then
    env_args+=(LD_LIBRARY_PATH="$LIB")
  else
    # shellcheck disable=SC2206 # MESA_ENV is a list of VAR=VALUE words
    env_args+=($MESA_ENV GALLIUM_DRIVER=llvmpipe)
  fi
  local start=$SECONDS
  # shellcheck disable=SC2086 # the list line carries the test's own arguments
  set +e
  (cd "$PIGLIT" && env "${env_args[@]}" timeout 120 "$BIN"/$line) >"$log" 2>&1
  status=$?
  set -e
  result=$(sed -n 's/.*PIGLIT: {"result": "\([a-z]*\)".*/\1/p' "$log" | tail -n1)
  if [ $status -eq 124 ]; then
    result=timeout
  elif [ -z "$result" ]; then
    result=crash
  fi
  echo "$result $((SECONDS - start))"
}
export -f run_one
export OUT LIB BIN PIGLIT MESA_ENV

one_line() {
  local line=$1 name p="- 0" m="-"
  name=$(line_name "$line")
  if [ "$PINEDA" = 1 ]; then
    p=$(run_one pineda "$line")
    if [ "$MESA" = 1 ]; then m=$(run_one mesa "$line" | cut -d' ' -f1); fi
    if [ "$MESA" = assumed ]; then m=pass; fi
  else
    m=$(run_one mesa "$line")
    p="- ${m##* }"
    m=${m%% *}
  fi
  printf '%s\t%s\t%s\t%s\n' "$name" "${p%% *}" "$m" "${p##* }"
}
export -f one_line
export MESA PINEDA

if [ "$CHECK_ONLY" = 0 ]; then
  tests/glx/run_with_xvfb.sh "$(command -v Xvfb)" bash -c "
    grep -v '^#' '$LIST' | grep -E -- '$FILTER' | tr '\\n' '\\0' |
      xargs -0 -P '$JOBS' -I{} bash -c 'one_line \"\$@\"' _ {}
  " | sort >"$OUT/results.tsv"
fi

total=$(wc -l <"$OUT/results.tsv")
# One awk, not a pipeline ending in grep -q: under pipefail, grep -q's early exit could make the
# writer fail with SIGPIPE and the test look unlisted.
expected() { awk -v n="$1" '!/^#/ && $1 == n {f = 1} END {exit !f}' "$EXPECT" 2>/dev/null; }
printf '%-55s %-8s %-8s %s\n' test pineda mesa note
bad=0
ext_skips=0
# The extension a Pineda skip needs, when piglit skipped for a missing extension.
missing_extension() {
  sed -n 's/.*\(Test requires\|unsupported extension\) \(GL_[A-Za-z0-9_]*\).*/\2/p' \
    "$OUT/logs/$1.pineda.log" 2>/dev/null | head -n1
}
while IFS=$'\t' read -r name p m secs; do
  note=""
  ext=""
  if [ "$p" = skip ]; then ext=$(missing_extension "$name"); fi
  if [ "$PINEDA" = 0 ]; then
    :
  elif [ "$m" = pass ] && [ -n "$ext" ] && ! expected "$name"; then
    note="skip: needs $ext, not advertised"
    ext_skips=$((ext_skips + 1))
  elif [ "$m" = pass ] && [ "$p" != pass ]; then
    if expected "$name"; then note="expected (expectations.txt)"; else note="UNEXPECTED"; bad=$((bad + 1)); fi
  elif [ "$p" = pass ] && expected "$name" &&
    ! awk -F'\t' -v n="$name" '$1 == n && $3 == "pass" && $2 != "pass" {f = 1} END {exit !f}' \
      "$OUT/results.tsv"; then
    # Stale only when no variant of the test (same name, other arguments) still fails.
    note="STALE expectation: passes now"; bad=$((bad + 1))
  fi
  printf '%-55s %-8s %-8s %s\n' "$name" "$p" "$m" "$note"
done <"$OUT/results.tsv"
echo
echo "piglit list $LIST: $total tests (results in $OUT/results.tsv, logs in $OUT/logs)"
for r in pass fail skip warn crash timeout; do
  p=$(awk -F'\t' -v r=$r '$2 == r' "$OUT/results.tsv" | wc -l)
  m=$(awk -F'\t' -v r=$r '$3 == r' "$OUT/results.tsv" | wc -l)
  printf '  %-8s pineda %4s   mesa %4s\n' "$r" "$([ "$PINEDA" = 1 ] && echo "$p" || echo -)" \
    "$([ "$MESA" != 0 ] && echo "$m" || echo -)"
done
if [ "$MESA" != 0 ] && [ "$PINEDA" = 1 ]; then
  echo "  passing on Mesa but not on Pineda: $(awk -F'\t' '$3 == "pass" && $2 != "pass"' "$OUT/results.tsv" | wc -l)"
  echo "    of which skipped for an extension Pineda does not advertise: $ext_skips"
  echo "  unexpected results (not in expectations.txt, or stale entries): $bad"
  [ "$bad" -eq 0 ]
fi
