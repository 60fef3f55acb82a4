#!/usr/bin/env bash
# Builds the sanitizer preset (ASan + UBSan, every report fatal) and runs the whole default
# test suite under it. A clean run means zero sanitizer reports.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset debug >/dev/null
cmake --build --preset debug -j "$(nproc)"
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:+$UBSAN_OPTIONS:}print_stacktrace=1"
ctest --preset debug -j "$(nproc)"
