#!/usr/bin/env bash
# analyze --json with --series-out: when the curves cannot be written, the JSON must not
# appear either (all outputs of a command are published together or not at all).
set -uo pipefail
cli=$1 record=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
touch "$work/file"
"$cli" analyze "$record" --json "$work/a.json" --series-out "$work/file" >/dev/null 2>&1
[ $? -eq 2 ] || { echo "a file in the way of --series-out: expected exit 2"; exit 1; }
[ -e "$work/a.json" ] && { echo "a.json left behind after a failed --series-out"; exit 1; }
mkdir -p "$work/curves/embedding.csv"
"$cli" analyze "$record" --json "$work/a.json" --series-out "$work/curves" >/dev/null 2>&1
[ $? -eq 2 ] || { echo "a directory in the way of a curve: expected exit 2"; exit 1; }
left=$(find "$work" -type f ! -name file | wc -l)
[ "$left" -eq 0 ] && [ ! -e "$work/a.json" ] || { echo "$left files left behind"; exit 1; }
"$cli" analyze "$record" --json "$work/b.json" --series-out "$work/ok" >/dev/null 2>&1 || exit 1
[ "$(ls "$work/ok" | wc -l)" -eq 7 ] && [ -s "$work/b.json" ] || { echo "outputs missing"; exit 1; }
echo "outputs all or none"
