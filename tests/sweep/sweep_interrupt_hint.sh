#!/usr/bin/env bash
# sweep_interrupt_hint.sh CLI: a sweep interrupted by SIGINT (Ctrl-C) or SIGTERM says where its
# finished runs are and that --resume finishes it; it ends by that signal, and the resume
# finishes the sweep.
set -uo pipefail
set -m  # background jobs in their own group with SIGINT at its default, as at a terminal
cli=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "$*"; cat "$work/err" 2>/dev/null | tail -n 5; exit 1; }
for sig in INT TERM; do
  rm -rf "$work/map" "$work/err"
  "$cli" sweep --grid circuit.S2_mm2=0.05:0.35:0.05 --repeats 3 --threads 1 --out "$work/map" \
    >/dev/null 2>"$work/err" &
  pid=$!
  # Wait until the journal holds a run, so the sweep is under way.
  for _ in $(seq 1 200); do
    [ -n "$(find "$work/map" -type f -size +0 2>/dev/null | head -n 1)" ] && break
    sleep 0.05
  done
  kill -s "$sig" "$pid"
  wait "$pid"
  code=$?
  [ "$code" -gt 128 ] || fail "SIG$sig: exit code $code, expected death by the signal"
  grep -q "sweep: interrupted; the finished runs are kept in $work/map: run the same command with --resume" \
    "$work/err" || fail "SIG$sig: no resume hint"
done
"$cli" sweep --grid circuit.S2_mm2=0.05:0.35:0.05 --repeats 3 --threads 1 --out "$work/map" \
  --resume >"$work/out" 2>"$work/err" || fail "the resume failed"
grep -q "7 points x 3 repeats = 21 runs" "$work/out" || fail "the resume did not finish the sweep"
echo "interrupt hint as expected"
