#!/usr/bin/env bash
# bench/verdict_vs_model_sweeps.sh: each --set reaches every sweep after the script's own
# (so it overrides them), --surrogates N reaches every sweep, and a --set without KEY=VALUE is
# refused with exit code 2. A stand-in
# for the CLI records its arguments and writes a one-run runs.csv, so no sweep is simulated.
set -euo pipefail
script=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/cli" <<'FAKE'
#!/bin/sh
echo "$*" >> "$CALLS"
while [ $# -ge 2 ]; do [ "$1" = "--out" ] && out=$2; shift; done
mkdir -p "$out"
printf 'point,repeat,ok,chaotic,lambda_per_s,lambda_uncertainty_per_s,lambda_model_per_s,lambda_model_uncertainty_per_s\n0,0,1,1,nan,nan,4.0,1.0\n' > "$out/runs.csv"
FAKE
chmod +x "$work/cli"
cd "$work"
export CALLS=$work/calls PNEUMACHAOS_CLI=$work/cli
sh "$script" --set run.duration_s=40 --set variation.texture_rel=0 > table.txt
[ "$(wc -l < calls)" -eq 8 ] || { echo "expected 8 sweeps:"; cat calls; exit 1; }
while read -r line; do
  case "$line" in
    *"--set run.duration_s=40 --set variation.texture_rel=0 --out"*) ;;
    *) echo "the --set options are not last before --out: $line"; exit 1 ;;
  esac
done < calls
grep -q -- "--set variation.texture_rel=0.02 --set run.duration_s=40" calls ||
  { echo "the script's own variation does not come first"; cat calls; exit 1; }
grep -qF '| **all** | 8 | 8 | 0 | 0 | 0 | 100.0 % | 0 |' table.txt || { cat table.txt; exit 1; }
CALLS=$work/calls2 sh "$script" --surrogates 39 > /dev/null
[ "$(grep -c -- "--surrogates 39 --out" calls2)" -eq 8 ] ||
  { echo "--surrogates does not reach every sweep:"; cat calls2; exit 1; }
if sh "$script" --set foo > /dev/null 2> err; then echo "--set foo was accepted"; exit 1; fi
grep -q "expected KEY=VALUE" err || { cat err; exit 1; }
echo "--set reaches every sweep last; a malformed --set is refused"
