#!/usr/bin/env bash
# Times the command line of two builds on the same records, alternately (old, new, old, new),
# and prints CPU seconds (user + sys), peak memory and the ratio old/new for each workload;
# it also checks that both builds write the same JSON. CPU time, not wall time: the machine
# may be shared (docs/notes/performance.md).
# Usage: bench/compare_builds.sh OLD_BUILD_DIR NEW_BUILD_DIR [--reproduce]
# (NEW_BUILD_DIR from `cmake --preset bench`; it provides bench/write_series.)
set -euo pipefail
old="$1/apps/pneumachaos/pneumachaos"
new="$2/apps/pneumachaos/pneumachaos"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$2/bench/write_series" lorenz 10000 > "$work/l1e4.csv"
"$2/bench/write_series" lorenz 100000 > "$work/l1e5.csv"
"$2/bench/write_series" lorenz 1000000 > "$work/l1e6.csv"
"$2/bench/write_series" noise 100000 > "$work/n1e5.csv"

# cpu_and_rss BINARY REPEATS ARGS...: CPU seconds per run and peak RSS [MB] of the last run.
cpu_and_rss() {
  local bin=$1 repeats=$2
  shift 2
  local total=0 line
  for _ in $(seq "$repeats"); do
    rm -rf "$work/report"  # reproduce would resume the previous run's sweeps
    /usr/bin/time -o "$work/time" -f "%U %S %M" "$bin" "$@" > /dev/null 2>&1
    line=$(tail -1 "$work/time")
    total=$(echo "$total $line" | awk '{printf "%.4f", $1 + $2 + $3}')
  done
  echo "$total $repeats $line" | awk '{printf "%.4f %.1f", $1 / $2, $5 / 1024}'
}

# workload NAME REPEATS ARGS...
workload() {
  local name=$1 repeats=$2
  shift 2
  local o1 n1 o2 n2
  o1=$(cpu_and_rss "$old" "$repeats" "$@")
  n1=$(cpu_and_rss "$new" "$repeats" "$@")
  o2=$(cpu_and_rss "$old" "$repeats" "$@")
  n2=$(cpu_and_rss "$new" "$repeats" "$@")
  printf "%-34s " "$name"
  echo "$o1 $n1 $o2 $n2" | awk '{o = ($1 + $5) / 2; n = ($3 + $7) / 2;
    printf "old %9.4f s %7.1f MB   new %9.4f s %7.1f MB   old/new %5.2f\n", o, $2, n, $4, o / n}'
}

printf "%-34s %s\n" "workload" "CPU seconds per run (mean of 2 alternating rounds), peak RSS"
workload "analyze 1e4 Lorenz (x10)" 10 analyze "$work/l1e4.csv" --surrogates 0
workload "analyze 1e5 Lorenz" 1 analyze "$work/l1e5.csv" --surrogates 0
workload "analyze 1e5 white noise" 1 analyze "$work/n1e5.csv" --surrogates 0
workload "analyze 1e6 Lorenz" 1 analyze "$work/l1e6.csv" --surrogates 0
workload "analyze 1e4 Lorenz, 39 surrogates" 1 analyze "$work/l1e4.csv"
if [[ "${3:-}" == "--reproduce" ]]; then
  workload "reproduce --quick" 1 reproduce --quick --out "$work/report"
fi

for f in l1e4 l1e5 n1e5 l1e6; do
  "$old" analyze "$work/$f.csv" --surrogates 0 --json "$work/$f.old.json" > /dev/null
  "$new" analyze "$work/$f.csv" --surrogates 0 --json "$work/$f.new.json" > /dev/null
  if cmp -s "$work/$f.old.json" "$work/$f.new.json"; then
    echo "$f: JSON identical"
  else
    echo "$f: JSON DIFFERS"
  fi
done
