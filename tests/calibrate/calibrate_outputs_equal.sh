# Sourced by the calibrate tests: every output of two calibration directories byte-identical.
calibrate_outputs=(journal.csv evaluations.csv best_scenario.toml claims.json calibration.json
                   summary.md figures/convergence.dat figures/convergence.png figures/convergence.svg)
same_outputs() {
  for f in "${calibrate_outputs[@]}"; do
    if ! cmp "$1/$f" "$2/$f"; then echo "differs: $f ($1 against $2)"; return 1; fi
  done
}
