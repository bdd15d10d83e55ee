#!/usr/bin/env bash
# Compares two image dumps of scripts/dump_images.sh byte for byte: every image and status
# line of A must exist in B with the same bytes. Prints the differing files; exit status 1 when
# any differs or is missing, 0 when all are identical.
# Usage: scripts/compare_images.sh DIR_A DIR_B
set -uo pipefail
if [ $# -ne 2 ]; then
  sed -n 2,5p "$0" >&2
  exit 2
fi
a=$1 b=$2
total=0 bad=0
while IFS= read -r -d '' f; do
  rel=${f#"$a"/}
  total=$((total + 1))
  if [ ! -e "$b/$rel" ]; then
    echo "missing in B: $rel"
    bad=$((bad + 1))
  elif ! cmp -s "$f" "$b/$rel"; then
    echo "differs: $rel"
    bad=$((bad + 1))
  fi
done < <(find "$a" -type f \( -name '*.rgba' -o -name '*.status' \) -print0 | sort -z)
echo "compare_images: $total files, $bad differ or are missing"
[ "$total" -gt 0 ] && [ "$bad" -eq 0 ]
