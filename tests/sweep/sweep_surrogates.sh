#!/usr/bin/env bash
# sweep --surrogates N runs the verdict's surrogate test on every record, seeded as `analyze`'s
# default: `analyze --surrogates N` on the replayed record must give each run's regime, and a
# resume with another N is refused (it is another sweep).
set -euo pipefail
cli=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Two runs the verdict calls stick-slip without surrogates and chaotic with them, on the
# compliant-mount rig (compliant_mount.toml) with volumes frozen at 420 mm
# (docs/notes/analysis.md, "Surrogate-data test").
rig="$(cd "$(dirname "$0")/../.." && pwd)/scenarios/variants/compliant_mount.toml"
args=(sweep "$rig" --grid circuit.S1_mm2=2.45:3.20:0.75 --grid circuit.S2_mm2=0.2:0.5:0.3 --repeats 1
      --set run.duration_s=10 --set cylinder.frozen_position_mm=420 --threads 2)
"$cli" "${args[@]}" --surrogates 19 --out "$work/map" >/dev/null
for at in "3.2,0.2" "2.45,0.5"; do
  # runs.csv: S1, S2, point, repeat, ...; the regime is column 18.
  point=$(awk -F, -v s1="${at%,*}" -v s2="${at#*,}" 'NR > 1 && $1 == s1 && $2 == s2 { print $3 }' \
          "$work/map/runs.csv")
  expected=$(awk -F, -v p="$point" 'NR > 1 && $3 == p { print $18 }' "$work/map/runs.csv")
  "$cli" "${args[@]}" --surrogates 19 --replay "$point:0" -o "$work/run.csv" 2>/dev/null
  got=$("$cli" analyze "$work/run.csv" --column v_measured --no-wolf --surrogates 19 |
        sed -n 's/^verdict: \([a-z-]*\).*/\1/p')
  [ -n "$got" ] && [ "$got" = "$expected" ] ||
    { echo "S1,S2 = $at: sweep says '$expected', analyze says '$got'"; exit 1; }
  # Without surrogates the same record is judged otherwise, so the check above has teeth.
  plain=$("$cli" analyze "$work/run.csv" --column v_measured --no-wolf --surrogates 0 |
          sed -n 's/^verdict: \([a-z-]*\).*/\1/p')
  [ "$plain" != "$got" ] || { echo "S1,S2 = $at: '$got' with and without surrogates"; exit 1; }
done
set +e
"$cli" "${args[@]}" --surrogates 39 --out "$work/map" --resume >"$work/log" 2>&1
code=$?
set -e
[ $code = 2 ] && grep -q -- "--surrogates" "$work/log" ||
  { echo "a resume with another --surrogates: exit $code"; cat "$work/log"; exit 1; }
echo "sweep and analyze agree with surrogates; another count is another sweep"
