#!/usr/bin/env bash
# run_fuzzer.sh HARNESS SEEDS_DIR CORPUS SECONDS [MAX_LEN SEED RUNS [SEED_FILE...]]
# Runs one libFuzzer harness for a bounded time from a scratch copy of its seed corpus (the
# directory's files and the seed files named after it) and prints the number of executions. Exits non-zero on a crash, a sanitizer report or a leak
# (libFuzzer writes the offending input as crash-*/leak-* in the working directory).
set -euo pipefail
harness=$1 seeds=$2 corpus=$3 seconds=$4 max_len=${5:-8192} seed=${6:-0} runs=${7:-0}
shift $(( $# < 7 ? $# : 7 ))
mkdir -p "$corpus"
cp -n "$seeds"/* "$corpus"/ 2>/dev/null || true
# A seed file kept elsewhere is copied under its directory's name too: two files of one name
# (tests/data/x.toml, scenarios/calibrations/x.toml) stay two seeds.
for file in "$@"; do
  cp -n "$file" "$corpus/$(basename "$(dirname "$file")")_$(basename "$file")"
done
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# seed 0: libFuzzer picks one (long campaigns); CI passes a fixed seed so that a run is
# repeatable up to where the time limit cuts it. runs 0: no limit on the executions (-1).
[ "$runs" -gt 0 ] || runs=-1
if ! "$harness" -seed="$seed" -runs="$runs" -max_total_time="$seconds" -max_len="$max_len" -timeout=20 -rss_limit_mb=4096 \
    -print_final_stats=1 "$corpus" >"$log" 2>&1; then
  tail -n 60 "$log"
  exit 1
fi
executed=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo 0)
echo "fuzz: $executed executions, no crash ($(basename "$harness"), ${seconds} s)"
