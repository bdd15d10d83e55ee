#!/usr/bin/env bash
# Every Debian package cmake/Dependencies.cmake names must be one scripts/deps.sh installs, so
# that the package a failed configure step asks for is the one the quick start brings.
# Run by ctest (deps.listed).
set -euo pipefail
cd "$(dirname "$0")/.."
named=$( (sed -nE 's/^ *pineda_require_(header|library|program)\([^ ]+ [^ ]+ ([^ )]+)\).*/\2/p' \
  cmake/Dependencies.cmake
  sed -nE 's/^ *pineda_require_file\("[^"]*" ([^ ]+) .*/\1/p' cmake/Dependencies.cmake
  sed -nE 's/^ *pineda_missing\("[^"]*" ([^ )]+)\).*/\1/p' cmake/Dependencies.cmake) |
  grep -v '^\$' | sort -u)
listed=$(sed -n '/^PACKAGES=(/,/^)/p' scripts/deps.sh | sed 's/#.*//' | tr -s ' ' '\n' | sort -u)
status=0
for p in $named; do
  if ! grep -qx "$p" <<<"$listed"; then
    echo "check_deps: cmake/Dependencies.cmake names $p, which scripts/deps.sh does not install"
    status=1
  fi
done
[ $status -eq 0 ] && echo "check_deps: all $(wc -w <<<"$named") packages named by the configure checks are in deps.sh"
exit $status
