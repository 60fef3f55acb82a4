#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default test suite (everything but the tests
# labelled "long", "fuzz" and "fuzz_long"; see README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
ctest --preset release -j "$(nproc)"
