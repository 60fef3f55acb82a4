#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job: `reproduce` on the built-in
# defaults, writing the report to report/index.html (about 2.5 minutes on 2 cores; run again
# after an interruption and it resumes its sweeps).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target pneumachaos
./build/apps/pneumachaos/pneumachaos reproduce --out report "$@"
