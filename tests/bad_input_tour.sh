#!/usr/bin/env bash
# bad_input_tour.sh CLI RIG TABLE [NAME]
# The bad-input tour (issue 33, docs/reliability.md "The bad-input tour"): every case of TABLE,
# or only the case NAME, run as `pneumachaos ARGS` in a work directory holding the fixtures
# below. A case passes when the exit code is exactly CODE, standard error and output together
# match the extended regex, and (for a non-zero code) the work directory is unchanged: no
# partial output left behind.
#
# TABLE: one case per line, fields separated by a TAB: NAME, CODE, REGEX, ARGS. ARGS is read
# by the shell (quotes, `<` redirection); $W is the work directory, $RIG the simple rig.
set -uo pipefail
cli=$(realpath "$1") RIG=$(realpath "$2") table=$3 only=${4:-}
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
export W RIG

# Fixtures: a default record (t, x, v, P1, P2, ...), the simple rig in stick-slip, its t and v
# columns without a header, a ';'-separated export with decimal commas, a short record.
"$cli" simulate --duration 4 -o "$W/rec.csv" 2>/dev/null || { echo "fixture rec.csv"; exit 1; }
"$cli" simulate "$RIG" --set circuit.S2_mm2=0.2 --duration 6 -o "$W/ss.csv" 2>/dev/null ||
  { echo "fixture ss.csv"; exit 1; }
tail -n +2 "$W/rec.csv" | cut -d, -f1,3 | tr ',' ' ' >"$W/tv.txt"
tail -n +2 "$W/rec.csv" | cut -d, -f1,3 | tr ',.' ';,' | sed '1i t;v' >"$W/semi.csv"
head -n 11 "$W/rec.csv" >"$W/short.csv"
awk -F, 'BEGIN{OFS=","} NR>1{$3=$3*1000} {print}' "$W/ss.csv" >"$W/ss_mm.csv"  # mm/s as m/s
mkdir "$W/adir"
# A named pipe stands for a device: a regression that renamed a finished file over `-o
# /dev/null` (as root) would replace the machine's /dev/null; over this pipe it harms nothing.
mkfifo "$W/pipe"

n=0 failed=0
while IFS=$'\t' read -r name code regex args; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  [[ -n "$only" && "$name" != "$only" ]] && continue
  n=$((n + 1))
  before=$(cd "$W" && find . | sort)
  out=$(cd "$W" && eval "\"\$cli\" $args" 2>&1)
  got=$?
  after=$(cd "$W" && find . | sort)
  why=""
  if [ "$got" -ne "$code" ]; then
    why="exit code $got, expected $code"
  elif ! grep -qE -- "$regex" <<<"$out"; then
    why="output does not match: $regex"
  elif [ "$code" -ne 0 ] && [ "$before" != "$after" ]; then
    why="the work directory changed: $(diff <(echo "$before") <(echo "$after") | tail -n +2 | tr '\n' ' ')"
  fi
  if [ -n "$why" ]; then
    failed=$((failed + 1))
    echo "FAILED $name: pneumachaos $args"
    echo "  $why"
    sed 's/^/  | /' <<<"$out" | head -n 8
  fi
  # Cases that succeed may write: start the next one from the fixtures alone.
  [ "$code" -eq 0 ] && (cd "$W" && comm -13 <(echo "$before") <(find . | sort) | sort -r |
    while read -r f; do rm -rf "$f"; done)
done <"$table"
if [ "$n" -eq 0 ]; then echo "no case named ${only:-any}"; exit 1; fi
[ "$failed" -eq 0 ] || { echo "$failed of $n cases failed"; exit 1; }
echo "bad-input tour: $n case(s) as expected"
