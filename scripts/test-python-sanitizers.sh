#!/usr/bin/env bash
# Builds the Python module with the sanitizer preset's flags (ASan + UBSan, every report
# fatal) and runs the pytest suite under them. It shares the `debug` preset's build tree, so
# after scripts/test-sanitizers.sh only the module itself is compiled; the preset's own
# configuration (Python off) is restored at the end. The interpreter's settings (the
# sanitizer runtimes preloaded, PYTHONMALLOC=malloc, leak detection off) and why each is
# needed are in python/CMakeLists.txt, where the test is defined.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
restore() { cmake --preset debug >/dev/null; }
trap restore EXIT
cmake --preset debug -DPNEUMACHAOS_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build --preset debug -j "$(nproc)" --target pneumachaos_python
ctest --test-dir build-debug --output-on-failure -R '^python\.'
