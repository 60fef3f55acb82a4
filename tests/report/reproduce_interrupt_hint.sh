#!/usr/bin/env bash
# reproduce_interrupt_hint.sh CLI: `reproduce` interrupted by SIGINT (Ctrl-C) says where its
# finished sweep runs are and that running it again continues; it ends by that signal. Run
# again it finishes, and names its report without a doubled slash when --out ends in one.
set -uo pipefail
set -m  # background jobs in their own group with SIGINT at its default, as at a terminal
cli=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "$*"; tail -n 5 "$work/err" 2>/dev/null; exit 1; }
"$cli" reproduce --quick --threads 1 --out "$work/r/" >/dev/null 2>"$work/err" &
pid=$!
for _ in $(seq 1 400); do
  [ -n "$(find "$work/r/sweeps" -type f -size +0 2>/dev/null | head -n 1)" ] && break
  sleep 0.05
done
kill -s INT "$pid"
wait "$pid"
code=$?
[ "$code" -gt 128 ] || fail "exit code $code, expected death by the signal"
grep -q "reproduce: interrupted; the finished sweep runs are kept in $work/r/sweeps: run the same command again" \
  "$work/err" || fail "no hint"
"$cli" reproduce --quick --out "$work/r/" >"$work/out" 2>"$work/err" || fail "the second run failed"
grep -q "report: $work/r/index.html\$" "$work/out" || fail "report path: $(tail -n 1 "$work/out")"
echo "reproduce interrupt hint as expected"
