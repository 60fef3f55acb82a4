#!/usr/bin/env bash
# The same spec and seed give byte-identical outputs at 1 and 2 threads; re-running a finished
# calibration with --resume replays its journal to the same outputs; another seed is refused.
set -euo pipefail
cli=$1
spec=$2
source "$(dirname "$0")/calibrate_outputs_equal.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$cli" calibrate "$spec" --out "$work/one" --threads 1 >/dev/null
"$cli" calibrate "$spec" --out "$work/two" --threads 2 >/dev/null
same_outputs "$work/one" "$work/two"
cp -r "$work/one" "$work/again"
"$cli" calibrate "$spec" --out "$work/again" --threads 2 --resume >/dev/null
same_outputs "$work/one" "$work/again"
# The journal holds every evaluation: 20 lines after its header.
[[ $(($(wc -l < "$work/one/journal.csv") - 1)) == 20 ]]
sed 's/^seed = 3/seed = 4/' "$spec" > "$work/other_seed.toml"
if "$cli" calibrate "$work/other_seed.toml" --out "$work/one" --resume 2>"$work/err"; then
  echo "a resume with another seed was accepted"; exit 1
fi
grep -q "another calibration's journal" "$work/err"
echo "identical at 1 and 2 threads and after a replay; another seed refused"
