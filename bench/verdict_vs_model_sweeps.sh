#!/bin/sh
# The record verdict against the model's own exponent, the four map conditions,
# rows S2 0.05-0.65 mm^2, with (2 runs) and without (1 run) seal variation: 360 runs, ~1 min on
# 2 cores (3 min with --relabel). Run from an empty directory; PNEUMACHAOS_CLI names the binary.
# usage: verdict_vs_model_sweeps.sh [--relabel] [--set KEY=VALUE ...] [--surrogates N]
# [SCENARIO.toml]  (the scenario goes to every sweep, e.g. scenarios/variants/gms_candidate.toml;
# default: the built-in scenario). --relabel runs the sweeps twice more with other settings of
# the model's exponent (renormalised every 0.04 s; 2 s of start-up discarded) and adds the
# table of runs whose label all three settings give (docs/notes/analysis.md, "Validation
# against the model's own exponent"). Each --set is passed to every sweep after the script's
# own, so it overrides them: e.g. --set run.duration_s=40 for 40 s records, --set
# variation.texture_rel=0 for seal variation without bore texture (docs/notes/analysis.md,
# "Validation against the model's own exponent": blind spots of a 10 s record). --surrogates N
# goes to every sweep too: the verdict with N IAAFT surrogates per
# record (docs/notes/analysis.md, "Surrogate-data test").
set -eu
cli=${PNEUMACHAOS_CLI:?set PNEUMACHAOS_CLI to the pneumachaos binary}
relabel=0
extra=""
while [ $# -ge 1 ]; do
  case "$1" in
    --relabel) relabel=1; shift ;;
    --set)
      [ $# -ge 2 ] || { echo "verdict_vs_model_sweeps.sh: --set needs KEY=VALUE" >&2; exit 2; }
      case "$2" in *=*) ;; *) echo "verdict_vs_model_sweeps.sh: --set '$2': expected KEY=VALUE" >&2; exit 2 ;; esac
      extra="$extra --set $2"; shift 2 ;;
    --surrogates)
      [ $# -ge 2 ] || { echo "verdict_vs_model_sweeps.sh: --surrogates needs N" >&2; exit 2; }
      extra="$extra --surrogates $2"; shift 2 ;;
    *) break ;;
  esac
done
scenario=""
if [ $# -ge 1 ]; then
  [ -f "$1" ] || { echo "verdict_vs_model_sweeps.sh: scenario file '$1' not found" >&2; exit 2; }
  scenario=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
fi

# run_sweeps PREFIX MODEL_OPTIONS: the eight sweeps into PREFIX{var,novar}_CONDITION
run_sweeps() {
  common="--grid circuit.S1_mm2=2.45:3.70:0.25 --grid circuit.S2_mm2=0.05:0.65:0.15 --model-exponent --model-measure 40 $2 --threads 2"
  for cond in "ps025_m15:" "ps030_m15:--set supply.pressure_MPa=0.30" "ps025_m30:--set load.mass_kg=3.0" "ps025_m45:--set load.mass_kg=4.5"; do
    name=${cond%%:*}; sets=${cond#*:}
    nice $cli sweep $scenario $common $sets --repeats 2 --set variation.friction_rel_sd=0.03 --set variation.texture_rel=0.02 $extra --out "$1var_$name" > "$1var_$name.log" 2>&1
    nice $cli sweep $scenario $common $sets --repeats 1 $extra --out "$1novar_$name" > "$1novar_$name.log" 2>&1
  done
}

run_sweeps "" ""
if [ $relabel = 1 ]; then
  run_sweeps "renorm04_" "--model-renormalize 0.04"
  run_sweeps "transient2_" "--model-transient 2"
  python3 "$(dirname "$0")/verdict_vs_model.py" var_*/runs.csv novar_*/runs.csv \
    --relabel renorm04_var_*/runs.csv renorm04_novar_*/runs.csv \
    --relabel transient2_var_*/runs.csv transient2_novar_*/runs.csv
else
  python3 "$(dirname "$0")/verdict_vs_model.py" var_*/runs.csv novar_*/runs.csv
fi
