#!/usr/bin/env bash
# mpirun -np 2 against 2 threads: the same calibration gives byte-identical outputs.
# Exits 77 (CTest: skipped) when the binary has no MPI or no launcher is installed.
set -euo pipefail
cli=$1
spec=$2
source "$(dirname "$0")/calibrate_outputs_equal.sh"
if ! "$cli" --version | grep -q "(MPI)"; then echo "skipped: built without MPI"; exit 77; fi
if ! command -v mpirun >/dev/null; then echo "skipped: no mpirun"; exit 77; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$cli" calibrate "$spec" --out "$work/threads" --threads 2 >/dev/null
# Root in containers and more ranks than cores must be allowed explicitly; Open MPI's start-up
# allocations are never freed by design, so leak checking is off under the sanitizer preset.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
mpirun --allow-run-as-root --oversubscribe -np 2 "$cli" calibrate "$spec" --out "$work/mpi" \
  --threads 1 >"$work/mpi.log"
# Both ranks ran the sweeps (rank 1's journal of the best point's map), one of them reported.
ls "$work/mpi/sweeps/best/base/journal.rank1.csv" >/dev/null
[[ $(grep -c "^calibrate:" "$work/mpi.log") == 1 ]]
same_outputs "$work/threads" "$work/mpi"
echo "2 MPI ranks and 2 threads identical"
