#!/usr/bin/env bash
# docs_cpp_example.sh BUILD_DIR [CXX_FLAGS]: the guide's C++ example (docs/guide/examples) as a
# user builds it: the build tree installed into a scratch prefix, the example configured with
# find_package(pneumachaos), built and run. Its output must hold the stability verdict and the
# record's regime, and the small map's counts (the example prints all three).
set -euo pipefail
build_dir=$1
cxx_flags=${2:-}
source_dir=$(cd "$(dirname "$0")/../docs/guide/examples" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$cxx_flags" >/dev/null
cmake --build "$work/build" -j2 >/dev/null
"$work/build/first_steps"
