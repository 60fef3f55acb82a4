#!/usr/bin/env bash
# bench/blind_records.py on the built CLI: no regular or stochastic record of the blind set
# may be called chaotic (docs/validation.md, the blind-records row). Skipped (77) without numpy.
set -euo pipefail
cli=$1
script=$2
python=""
for candidate in /usr/bin/python3 python3; do
  if "$candidate" -c "import numpy" 2>/dev/null; then python=$candidate; break; fi
done
[ -n "$python" ] || { echo "no python3 with numpy: skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$python" "$script" "$work" --cli "$cli"
