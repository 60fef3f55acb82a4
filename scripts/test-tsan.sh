#!/usr/bin/env bash
# Builds the ThreadSanitizer preset and runs the tests labelled `parallel` under it (the
# sweeps on oneTBB threads: the runner, the journal, kill/resume, --replay, adaptive maps;
# the report's progress ticker). The preset sets PNEUMACHAOS_PARALLEL_TESTS_ONLY, so only the
# gtest files holding such tests are compiled, as one executable (tests/CMakeLists.txt). A
# clean run means zero ThreadSanitizer reports: any report makes the process exit non-zero
# (exitcode=66), so its test fails. The label and how to give it to a new test:
# tests/CMakeLists.txt; suppressions: scripts/tsan.supp.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset tsan >/dev/null
cmake --build --preset tsan -j "$(nproc)" --target parallel_tests pneumachaos
export TSAN_OPTIONS="${TSAN_OPTIONS:+$TSAN_OPTIONS:}halt_on_error=1:exitcode=66:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp"
ctest --preset tsan -j "$(nproc)"
