#!/usr/bin/env bash
# Installs every Debian package that building, testing and running pneumachaos needs.
# Idempotent: when everything is already installed it prints nothing and touches nothing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libboost-dev libboost-math-dev
  libnanoflann-dev libkissfft-dev
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libceres-dev libtbb-dev
  libpagmo-dev
  gnuplot-nox
  mkdocs doxygen
  chromium
  libopenmpi-dev openmpi-bin
  clang libclang-rt-14-dev
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib
  nodejs
)
# npm for the browser tests' driver: Debian's package only where no npm is on the PATH (a
# Node.js from elsewhere, e.g. NodeSource's, brings its own and conflicts with Debian's).
command -v npm >/dev/null || packages+=(npm)

# The browser tests' driver (tests/browser/package-lock.json pins puppeteer-core) drives the
# chromium above: no browser download. Installed again only when the lock file changes.
browser_tests() {
  local dir stamp
  dir=$(cd "$(dirname "$0")/../tests/browser" && pwd)
  stamp=$dir/node_modules/.package-lock.json
  command -v npm >/dev/null || { echo "setup: npm not found: the browser tests will be skipped" >&2; return 0; }
  [ -f "$stamp" ] && [ "$stamp" -nt "$dir/package-lock.json" ] && return 0
  echo "setup: npm ci in tests/browser (puppeteer-core, no browser download)" >&2
  (cd "$dir" && PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error >/dev/null)
}

install_missing() {
  local missing=() p
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}
install_missing
browser_tests
