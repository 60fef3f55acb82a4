#!/usr/bin/env bash
# bad_input_tour.sh CLI RIG TABLE [NAME]
# The bad-input tour (docs/reliability.md "The bad-input tour"): every case of TABLE,
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
# Unit mistakes (docs/reference/record-units.md): a clock in ms headed t[ms] (read
# right) and headed t[s]; pressures in kPa, and gauge pressures, headed [Pa]; calibration specs
# whose records are those files (one with its units in the spec), or a file that does not exist.
ms_clock() { awk -F, -v h="$2" 'BEGIN{OFS=","} NR==1{$1=h} NR>1{$1=$1*1000} {print}' "$W/$1"; }
ms_clock rec.csv 't[ms]' >"$W/rec_ms.csv"
ms_clock rec.csv 't[s]' >"$W/rec_ms_as_s.csv"
ms_clock ss.csv 't[ms]' >"$W/ss_ms.csv"
awk -F, 'BEGIN{OFS=","} NR>1{$4=$4/1000; $5=$5/1000} {print}' "$W/ss.csv" >"$W/ss_kpa.csv"
awk -F, 'BEGIN{OFS=","} NR>1{$4=$4-101325; $5=$5-101325} {print}' "$W/ss.csv" >"$W/ss_gauge.csv"
sed '1s/\[[^]]*\]//g' "$W/ss_gauge.csv" >"$W/ss_gauge_bare.csv"  # t,x,v,P1,P2,...
tail -n +2 "$W/rec_ms.csv" | cut -d, -f1,3 | sed '1i t,v' >"$W/tv_ms.csv"
sed '1s/^t\[s\]/t[min]/' "$W/rec.csv" >"$W/rec_min.csv"
for r in ss_kpa ss_gauge ss_missing ss_gauge_bare; do
  printf '[[free]]\nkey = "friction.Fc_N"\nlower = 15\nupper = 35\nsource = "a catalogue"\n\n[objective]\nkind = "records"\nrecords = [ { file = "%s.csv" } ]\n' "$r" >"$W/cal_$r.toml"
done
sed -i 's/"ss_gauge_bare.csv" }/"ss_gauge_bare.csv", units = { P1 = "Pa g", P2 = "Pa gauge" } }/' \
  "$W/cal_ss_gauge_bare.toml"  # the units given in the spec, and a short run
printf '\n[optimizer]\npopulation = 5\nmax_evaluations = 10\n' >>"$W/cal_ss_gauge_bare.toml"
printf '\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x10' >"$W/bin.csv"  # an image under a record's name
mkdir "$W/adir"
# A named pipe stands for a device: the outputs must write into a device, never rename a
# finished file over it (over `-o /dev/null` as root that would replace the machine's
# /dev/null); over this pipe a failure harms nothing.
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
