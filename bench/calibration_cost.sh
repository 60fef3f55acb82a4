#!/usr/bin/env bash
# What one calibration of the paper costs (the goal: a few hundred evaluations within
# an hour on 2 cores, scaling across MPI ranks). Runs `calibrate` on scenarios/calibrations/paper.toml
# with max_evaluations set to EVALUATIONS (default 30), on one thread, on two threads and, when
# the binary has MPI and mpirun is installed, on 2 ranks of one thread each; prints the wall
# and CPU time per accepted evaluation of each and the wall time 300 accepted evaluations would
# take at that rate. CPU is user + sys of the whole process tree; the machine should be otherwise idle.
# Usage: bench/calibration_cost.sh BUILD_DIR [EVALUATIONS]
set -euo pipefail
cli="$1/apps/pneumachaos/pneumachaos"
evaluations=${2:-30}
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed "s/^max_evaluations = .*/max_evaluations = $evaluations/" "$here/scenarios/calibrations/paper.toml" \
  > "$work/spec.toml"
grep -q "^max_evaluations = $evaluations$" "$work/spec.toml"

# run NAME COMMAND...: one calibration into a fresh directory; prints the per-evaluation
# figures over the evaluations the model accepted. evaluations.csv has one row per evaluation;
# a point the model refuses (e.g. a Coulomb gain above the static one) costs nothing and is
# written with objective 1 and no margin (column 9, then "nan"s), so it is not counted.
run() {
  local name=$1
  shift
  rm -rf "$work/out"
  /usr/bin/time -o "$work/time" -f "%e %U %S" "$@" --out "$work/out" > /dev/null 2> "$work/log"
  local made accepted
  made=$(($(wc -l < "$work/out/evaluations.csv") - 1))
  accepted=$(awk -F, 'NR > 1 && !($9 == 1 && $10 == "nan" && $NF == "nan")' \
    "$work/out/evaluations.csv" | wc -l)
  read -r wall user sys < "$work/time"
  awk -v n="$name" -v m="$made" -v a="$accepted" -v w="$wall" \
    -v c="$(echo "$user $sys" | awk '{print $1 + $2}')" \
    'BEGIN {printf "%-24s %5d %8d %10.1f %10.1f %12.2f %12.2f %14.1f\n", n, m, a, w, c, w / a, c / a, 300 * w / a / 60}'
}

printf "%-24s %5s %8s %10s %10s %12s %12s %14s\n" run evals accepted "wall [s]" "CPU [s]" \
  "wall/eval" "CPU/eval" "300 evals [min]"
run "1 thread" "$cli" calibrate "$work/spec.toml" --threads 1
run "2 threads" "$cli" calibrate "$work/spec.toml" --threads 2
if "$cli" --version | grep -q "(MPI)" && command -v mpirun > /dev/null; then
  run "2 MPI ranks x 1 thread" mpirun --allow-run-as-root --oversubscribe -np 2 \
    "$cli" calibrate "$work/spec.toml" --threads 1
else
  echo "2 MPI ranks: skipped (no MPI in the build or no mpirun)"
fi
