#!/usr/bin/env bash
# The command-line program runs six commands itself and opens libpneumachaos_cli.so for the
# others (docs/architecture.md "Modules opened at run time"): a copy of the program without
# its modules still runs its own commands, and for one held by the module stops with exit 3 naming
# the paths it tried.
set -euo pipefail
cli=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$cli" "$work/alone"
"$work/alone" scenario >/dev/null
set +e
"$work/alone" fit --help >/dev/null 2>"$work/log"
code=$?
set -e
if [[ $code != 3 ]] || ! grep -q "$work/libpneumachaos_cli.so" "$work/log"; then
  echo "a missing module: exit $code"; cat "$work/log"; exit 1
fi
"$cli" fit --help | grep -q "record" || { echo "fit --help beside its module failed"; exit 1; }
echo "light commands without the module; a missing module named, exit 3"
