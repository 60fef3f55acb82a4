#!/usr/bin/env bash
# Instructions of a whole `pneumachaos analyze --surrogates 0` against TISEAN 3.0.1's `mutual`
# + `lyap_r` (Hegger, Kantz & Schreiber 1999) on the same records, as valgrind's callgrind
# counts them (Ir of every instruction of each process, start-up included): a machine-
# independent measure of cost. TISEAN is given the embedding our analysis chose (dimension,
# delay, Theiler window, horizon) and asked for mutual information up to three delays (at
# least 20 lags), as an expert who already knew the embedding would; it neither chooses the
# embedding nor judges the regime, so the comparison flatters it.
# Usage: bench/tisean_cost.sh BUILD_DIR TISEAN_SOURCE_DIR
# (BUILD_DIR from `cmake --preset bench`: it provides bench/write_series; TISEAN_SOURCE_DIR is
# TISEAN 3.0.1's top directory, whose source_c/ is built here with gcc -O2.)
set -euo pipefail
build=$1
tisean=$2
cli="$build/apps/pneumachaos/pneumachaos"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir -p "$work/tisean"
cp -r "$tisean/source_c/." "$work/tisean/"
(cd "$work/tisean/routines" && rm -f ./*.o && for f in *.c; do gcc -O2 -w -c "$f"; done &&
 ar rcs libddtsa.a ./*.o)
for p in mutual lyap_r; do
  gcc -O2 -w -o "$work/$p" "$work/tisean/$p.c" "$work/tisean/routines/libddtsa.a" -lm
done

# instructions COMMAND...: callgrind's total Ir of the whole process.
instructions() {
  valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "$@" > /dev/null 2> "$work/cg.log"
  awk '/Collected/ {print $NF}' "$work/cg.log"
}

# cpu COMMAND...: user + system seconds of the whole process (for white noise, where lyap_r's
# box search in dimension 7 takes minutes natively and would take hours under callgrind).
cpu() {
  /usr/bin/time -o "$work/time" -f "%U %S" "$@" > /dev/null 2>&1
  awk '{printf "%.2f", $1 + $2}' "$work/time"
}

printf "%-22s %14s %14s %8s  %s\n" workload pneumachaos tisean ratio "TISEAN settings"
for spec in lorenz:10000 lorenz:100000 rossler:10000 henon:10000 noise:100000; do
  kind=${spec%%:*}
  n=${spec##*:}
  rec="$work/$kind$n.csv"
  "$build/bench/write_series" "$kind" "$n" > "$rec"
  tail -n +2 "$rec" | cut -d, -f2 > "$work/values.dat"
  "$cli" analyze "$rec" --surrogates 0 --json "$work/a.json" --series-out "$work/curves" > /dev/null
  read -r m tau theiler < <(python3 -c "
import json; e = json.load(open('$work/a.json'))['embedding']
print(e['dimension'], e['delay_samples'], e['theiler_samples'])")
  steps=$(($(wc -l < "$work/curves/divergence.csv") - 2))
  measure=instructions
  [ "$kind" = noise ] && measure=cpu
  ours=$($measure "$cli" analyze "$rec" --surrogates 0)
  lags=$((3 * tau > 20 ? 3 * tau : 20))  # past the first minimum, as an expert would ask
  mi=$($measure "$work/mutual" -D "$lags" -o "$work/mi.out" "$work/values.dat")
  lr=$($measure "$work/lyap_r" -m "$m" -d "$tau" -t "$theiler" -s "$steps" -o "$work/lr.out" \
       "$work/values.dat")
  theirs=$(awk -v a="$mi" -v b="$lr" 'BEGIN {printf (a + b == int(a + b) ? "%.0f" : "%.2f"), a + b}')
  [ "$kind" = noise ] && kind="noise (CPU s)"
  printf "%-22s %14s %14s %8s  %s\n" "$kind $n" "$ours" "$theirs" \
    "$(awk -v a="$ours" -v b="$theirs" 'BEGIN {printf "%.3g", a / b}')" \
    "lyap_r -m $m -d $tau -t $theiler -s $steps; mutual -D $lags"
done
echo "ratio = pneumachaos / TISEAN (below 1: pneumachaos costs less); instructions, except CPU seconds where said"
