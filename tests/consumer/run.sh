#!/usr/bin/env bash
# run.sh BUILD_DIR [CXX_FLAGS [SOURCE_DIR PROGRAM]]: installs the build tree into a scratch
# prefix, then configures the project in SOURCE_DIR (default: this consumer) against it with
# find_package(pneumachaos), builds it and runs PROGRAM (default: consumer), as a user would.
set -euo pipefail
build_dir=$1
# The project is compiled with the flags the library was built with (e.g. the sanitizer
# preset's), or it could not link against it.
cxx_flags=${2:-}
source_dir=$(cd "${3:-$(dirname "$0")}" && pwd)
program=${4:-consumer}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$cxx_flags" >/dev/null
cmake --build "$work/build" -j2 >/dev/null
"$work/build/$program"
