#!/usr/bin/env bash
# calibrate with a records objective from the command line: a record written by `simulate`
# beside the spec (its path relative to the spec's folder), the outputs naming it; a spec whose
# record is missing is refused with exit code 2 naming the file before any evaluation.
set -euo pipefail
cli=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/rig"
"$cli" simulate --set load.coupling=rigid --set friction.model=stribeck --set friction.Fc_N=25 \
  --duration 2 -o "$work/rig/run.csv" 2>/dev/null
spec() {
  cat <<TOML
[[free]]
key = "friction.Fc_N"
lower = 15
upper = 35
source = "a catalogue"

[fixed]
load.coupling = "rigid"
friction.model = "stribeck"

[objective]
kind = "records"
records = [ { file = "$1" } ]

[optimizer]
population = 5
max_evaluations = 20
seed = 2
TOML
}
spec run.csv > "$work/rig/spec.toml"
"$cli" calibrate "$work/rig/spec.toml" --out "$work/out" --threads 1 > "$work/log"
grep -Eq "^calibrate: 20 evaluations; best: evaluation [0-9]+, objective [0-9.]+; record errors [0-9.e+-]+, predicted 0 of 0" "$work/log" || { cat "$work/log"; exit 1; }
grep -q "| $work/rig/run.csv | " "$work/out/summary.md"
grep -q '"record_errors"' "$work/out/calibration.json"
head -n 1 "$work/out/evaluations.csv" | grep -q "^evaluation,friction.Fc_N,objective,record_1_error$"
spec missing.csv > "$work/rig/missing.toml"
if "$cli" calibrate "$work/rig/missing.toml" --out "$work/never" 2> "$work/err"; then
  echo "a missing record was accepted"; exit 1
else
  code=$?
fi
[[ $code == 2 ]] || { echo "exit code $code"; cat "$work/err"; exit 1; }
grep -q "missing.csv" "$work/err"
[[ ! -e "$work/never/journal.csv" ]]
echo "records objective: outputs name the record; a missing record refused"
