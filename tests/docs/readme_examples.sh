#!/usr/bin/env bash
# readme_examples.sh CLI README RIG [PYTHON PYTHONPATH]: runs every `pneumachaos` command of the README's ```sh
# blocks as written, in README order, in one work directory; each must exit 0.
# The guide's commands are run by tests/docs/docs_site.sh the same way.
# The lines are taken from the README mechanically: a block's lines that start with
# `pneumachaos` or `mpirun`, or pipe into `pneumachaos`, joined across a trailing backslash,
# with the trailing comment cut. The others (build and test scripts, cmake, benchmarks) are
# the suite's own steps. Skipped, and why, below (SKIP); a skip that matches no line fails,
# so the list cannot go stale. With PYTHON, each ```python block runs too, as one script.
set -uo pipefail
cli=$(realpath "$1") readme=$(realpath "$2") rig=$(realpath "$3")
python=${4:-} pythonpath=${5:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bin="$work/bin"
mkdir -p "$bin" && ln -s "$cli" "$bin/pneumachaos"
export PATH="$bin:$PATH"

# Long jobs, each run elsewhere in the suite on a smaller scale: pattern -> reason. The README
# keeps only quick examples (the guide's pages hold the rest, run by tests/docs/docs_site.sh).
declare -A SKIP=()

# The files the examples read, as a user would have them: their own cylinder (the simple
# rig), a rig record with P1, P2 and v (also under the names vel, pA, pB) and a lab export
# with a header line and blank-separated columns.
cd "$work" || exit 1
cp "$rig" my_rig.toml
cp "$rig" my_rig.pristine
ln -s "$(dirname "$readme")/docs" docs  # the README's paths are from the repository root
pneumachaos simulate "$rig" --set circuit.S2_mm2=0.2 --duration 6 -o rec.csv 2>/dev/null || exit 1
awk -F, 'BEGIN{OFS=","} NR==1{print $0,"vel[m/s]","pA[Pa]","pB[Pa]"; next} {print $0,$3,$4,$5}' \
  rec.csv >rig.csv
{ echo "time velocity"; tail -n +2 rec.csv | cut -d, -f1,3 | tr ',' ' '; } >lab.dat

commands=$(awk '
  /^```sh/ {block = 1; next}
  /^```/ {block = 0; next}
  block {
    line = (pending != "" ? pending " " : "") $0
    if (line ~ /\\$/) { sub(/[ ]*\\$/, "", line); pending = line; next }
    pending = ""
    sub(/^[ ]+/, "", line)
    sub(/[ ]+#.*$/, "", line)
    if (line ~ /^pneumachaos / || line ~ /^mpirun / || line ~ /\| *pneumachaos /) print line
  }' "$readme")

declare -A used=()
ran=0 skipped=0 failed=0
while IFS= read -r cmd; do
  [ -z "$cmd" ] && continue
  if [ -n "${SKIP[$cmd]+x}" ]; then
    used["$cmd"]=1
    skipped=$((skipped + 1))
    echo "skipped: $cmd  (${SKIP[$cmd]})"
    continue
  fi
  ran=$((ran + 1))
  # Every example reads the same "own cylinder": `scenario > my_rig.toml` (the virtual rig,
  # whose fit takes minutes) does not become the cylinder of the examples after it.
  cp my_rig.pristine my_rig.toml
  start=$(date +%s.%N)
  if ! out=$(bash -c "$cmd" 2>&1 >/dev/null); then
    failed=$((failed + 1))
    echo "FAILED: $cmd"
    tail -n 5 <<<"$out" | sed 's/^/  | /'
  fi
  [ -n "${README_TIMES:-}" ] && echo "$(echo "$(date +%s.%N) - $start" | bc) s: $cmd"
done <<<"$commands"
if [ -n "$python" ]; then
  awk '/^```python/ {block = 1; n++; next} /^```/ {block = 0; next}
       block {print > ("readme_" n ".py")}' "$readme"
  for script in readme_*.py; do
    [ -e "$script" ] || continue
    ran=$((ran + 1))
    if ! out=$(PYTHONPATH="$pythonpath" "$python" "$script" 2>&1); then
      failed=$((failed + 1))
      echo "FAILED: the README's Python example $script"
      tail -n 5 <<<"$out" | sed 's/^/  | /'
    fi
  done
fi
for pattern in "${!SKIP[@]}"; do
  [ -n "${used[$pattern]+x}" ] || { echo "a skip matches no README line: $pattern"; failed=$((failed + 1)); }
done
[ "$failed" -eq 0 ] || { echo "$failed README example(s) failed"; exit 1; }
echo "README examples: $ran ran as written, $skipped long ones skipped"
