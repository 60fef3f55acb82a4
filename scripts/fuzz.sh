#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan) and runs each for a bounded time:
#   scripts/fuzz.sh            60 s each (the `fuzz` label; part of CI)
#   scripts/fuzz.sh long       4 hours each (the `fuzz_long` label)
#   PNEUMACHAOS_FUZZ_SECONDS=N scripts/fuzz.sh    N seconds each
# A crash leaves its input as crash-* in build-fuzz/fuzz; docs/reliability.md says more.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset fuzz -DPNEUMACHAOS_FUZZ_SECONDS="${PNEUMACHAOS_FUZZ_SECONDS:-60}" >/dev/null
cmake --build --preset fuzz -j "$(nproc)" --target fuzzers
label=fuzz
[ "${1:-}" = "long" ] && label=fuzz_long
# The harnesses run one at a time: each uses one core, and 2-core machines also build.
ctest --test-dir build-fuzz --output-on-failure -L "^${label}\$"
