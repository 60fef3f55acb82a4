#!/usr/bin/env bash
# expect_exit.sh [--stdout FILE] CODE REGEX CMD [ARG...]
# Passes when CMD exits with exactly CODE and its standard error (and standard output, unless
# --stdout sends that to FILE, e.g. /dev/full) matches the extended regex REGEX.
set -uo pipefail
stdout=""
if [ "$1" = "--stdout" ]; then stdout=$2; shift 2; fi
code=$1 regex=$2
shift 2
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if [ -n "$stdout" ]; then "$@" >"$stdout" 2>"$log"; else "$@" >"$log" 2>&1; fi
got=$?
if [ "$got" -ne "$code" ]; then
  echo "expected exit code $code, got $got"; tail -n 20 "$log"; exit 1
fi
if ! grep -qE -- "$regex" "$log"; then
  echo "exit code $code, but the output does not match: $regex"; tail -n 20 "$log"; exit 1
fi
echo "exit code $code and message as expected"
