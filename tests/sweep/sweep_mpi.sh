#!/usr/bin/env bash
# mpirun -np 2 against a local run on a small grid: identical result files. Exits 77 (CTest:
# skipped) with a message when the binary has no MPI or no launcher is installed.
set -euo pipefail
cli=$1
if ! "$cli" --version | grep -q "(MPI)"; then echo "skipped: built without MPI"; exit 77; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# MPI is a module opened only under a launcher: a program without it beside it must stop with
# exit 3 and name where it looked (a launcher's variable set by hand stands in for mpirun).
cp "$cli" "$work/alone"
set +e
OMPI_COMM_WORLD_SIZE=1 "$work/alone" sweep --grid circuit.S2_mm2=0.05:0.35:0.15 --out "$work/x" \
  >/dev/null 2>"$work/alone.log"
code=$?
set -e
if [[ $code != 3 ]] || ! grep -q "$work/libpneumachaos_mpi.so" "$work/alone.log"; then
  echo "missing MPI module: exit $code"; cat "$work/alone.log"; exit 1
fi
if ! command -v mpirun >/dev/null; then echo "skipped: no mpirun"; exit 77; fi
args=(sweep --grid circuit.S1_mm2=2.6:2.8:0.1 --grid circuit.S2_mm2=0.05:0.65:0.15 --repeats 2
      --set run.duration_s=3 --set variation.friction_rel_sd=0.05)
"$cli" "${args[@]}" --out "$work/local" >/dev/null
# Root in containers and more ranks than cores must be allowed explicitly. Under the sanitizer
# preset, Open MPI's own start-up allocations (never freed by design) would be reported as
# leaks at exit: leak checking is off for the ranks, every other ASan check stays on.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
mpirun --allow-run-as-root --oversubscribe -np 2 "$cli" "${args[@]}" --out "$work/mpi" >/dev/null
ls "$work/mpi"/journal.rank1.csv >/dev/null  # both ranks took part
for f in runs.csv points.csv summary.json; do cmp "$work/local/$f" "$work/mpi/$f"; done
# An adaptive map: its rounds are batches over the ranks, each rank reading all journals.
"$cli" "${args[@]}" --adaptive --adaptive-step 2 --out "$work/local_adaptive" >/dev/null
mpirun --allow-run-as-root --oversubscribe -np 2 "$cli" "${args[@]}" --adaptive \
  --adaptive-step 2 --out "$work/mpi_adaptive" >/dev/null
for f in runs.csv points.csv summary.json; do cmp "$work/local_adaptive/$f" "$work/mpi_adaptive/$f"; done
# One rank cannot open its journal (a directory stands in its place): every rank must stop
# with a message, none may wait forever for the failed one.
mkdir -p "$work/broken/journal.rank1.csv"
if timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 "$cli" "${args[@]}" \
    --out "$work/broken" --resume >"$work/broken.log" 2>&1; then
  echo "a rank that cannot write its journal was not reported"; exit 1
fi
grep -q "a directory stands where the journal must be written" "$work/broken.log" || { cat "$work/broken.log"; exit 1; }
grep -q "another MPI rank failed" "$work/broken.log" || { cat "$work/broken.log"; exit 1; }
echo "mpirun -np 2 and the local run wrote identical files; a failed rank stops all"
