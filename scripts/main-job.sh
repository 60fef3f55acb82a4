#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job on the built-in defaults.
# Until `reproduce` exists this is `simulate` on the default scenario, written to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target pneumachaos
mkdir -p out
./build/apps/pneumachaos/pneumachaos scenario > out/scenario.toml
./build/apps/pneumachaos/pneumachaos simulate -o out/simulate.csv
echo "wrote out/scenario.toml and out/simulate.csv"
