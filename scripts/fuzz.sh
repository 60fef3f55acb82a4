#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan) and runs each for a bounded time:
#   scripts/fuzz.sh            60 s each (the `fuzz` label; part of CI)
#   scripts/fuzz.sh long       4 hours each (the `fuzz_long` label)
#   PNEUMACHAOS_FUZZ_SECONDS=N scripts/fuzz.sh         N seconds each
#   PNEUMACHAOS_FUZZ_SECONDS=N scripts/fuzz.sh long    the long campaign, N seconds each
#   PNEUMACHAOS_FUZZ_RUNS=M ...                         also stop each after M executions
#   PNEUMACHAOS_FUZZ_ONLY=REGEX ...                     only the harnesses whose name matches
# A crash leaves its input as crash-* in build-fuzz/fuzz; docs/reliability.md and
# docs/notes/reliability_checks.md say more.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
label=fuzz
seconds=(-DPNEUMACHAOS_FUZZ_SECONDS="${PNEUMACHAOS_FUZZ_SECONDS:-60}")
if [ "${1:-}" = "long" ]; then
  label=fuzz_long
  seconds=(-DPNEUMACHAOS_FUZZ_LONG_SECONDS="${PNEUMACHAOS_FUZZ_SECONDS:-14400}")
fi
cmake --preset fuzz "${seconds[@]}" -DPNEUMACHAOS_FUZZ_RUNS="${PNEUMACHAOS_FUZZ_RUNS:-0}" >/dev/null
cmake --build --preset fuzz -j "$(nproc)" --target fuzzers
# Each harness uses one core for its seconds; once the build is done they run as many at a
# time as there are cores (each keeps its own corpus directory).
ctest --test-dir build-fuzz --output-on-failure -j "$(nproc)" -L "^${label}\$" \
  -R "${PNEUMACHAOS_FUZZ_ONLY:-.}"
