#!/usr/bin/env bash
# Start-up CPU of whole commands: the module build (pneumachaos) against the command line
# linked plainly (pneumachaos_linked) and linked without calibrate (pneumachaos_linked_nocal),
# alternately, three rounds of `perf stat -r 50` each (docs/notes/performance.md, "Start-up").
# Usage: bench/startup_variants.sh [BUILD]   (BUILD from `cmake --preset bench`, default build)
set -euo pipefail
build=${1:-build}
app="$build/apps/pneumachaos/pneumachaos"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$app" simulate --set circuit.S2_mm2=0.05 --duration 10 -o "$work/rec.csv" 2>/dev/null
run() {  # LABEL ARGS...
  local label=$1
  shift
  for prog in "$app" "$build/bench/pneumachaos_linked" "$build/bench/pneumachaos_linked_nocal"; do
    perf stat -r 50 -e task-clock "$prog" "$@" 2>&1 >/dev/null |
      awk -v p="$(basename "$prog")" -v l="$label" \
        '/task-clock/ {tc = $1} END {printf "%s | %s | %s ms CPU\n", l, p, tc}'
  done
}
for round in 1 2 3; do
  echo "round $round"
  run "--help" --help
  run "simulate --duration 0.1" simulate --duration 0.1
  run "scenario" scenario
  run "analyze 1e4 --surrogates 0" analyze "$work/rec.csv" --surrogates 0
done
