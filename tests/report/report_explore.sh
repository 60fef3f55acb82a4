#!/usr/bin/env bash
# report_explore.sh CLI: writes a quick report and explores it in headless Chromium through
# puppeteer-core (tests/browser/explore_report.mjs): a map cell's tooltip and runs against
# runs.csv, its runs' charts against runs/FIGURE.js and runs.csv, the same cell marked on the
# other maps, a claim's link and marked cells, no console message, no network, usable within
# 2 s, screenshots at two widths. Exits 77 (CTest's SKIP_RETURN_CODE) when node, chromium or
# tests/browser/node_modules (scripts/setup.sh installs them) are missing.
set -uo pipefail
cli=$1
here=$(cd "$(dirname "$0")" && pwd)
command -v node >/dev/null || { echo "SKIP: node is not installed"; exit 77; }
browser=$(command -v chromium || command -v chromium-browser) || {
  echo "SKIP: chromium is not installed (scripts/setup.sh installs it)"; exit 77; }
[ -d "$here/../browser/node_modules/puppeteer-core" ] || {
  echo "SKIP: tests/browser/node_modules is missing (scripts/setup.sh runs npm ci there)"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$cli" reproduce --quick --out "$dir/report" >/dev/null || exit 1
echo "report folder: $(du -sm "$dir/report" | cut -f1) MB"
# The screenshots stay beside the test's working directory for a reader to look at.
mkdir -p screenshots
node "$here/../browser/explore_report.mjs" "$dir/report" "$browser" "$PWD/screenshots" || exit 1
# The panel's command for the Fig. 4 map's first run gives that run's runs.csv line again, to
# the last digit (sweep --replay prints it on standard error, one field a line).
IFS=$'\t' read -r cmd line < <(python3 -c 'import json,sys
s=open(sys.argv[1]).read(); m=json.loads(s[s.index("{"):s.rindex(";")])["maps"][0]
c=next(c for c in m["cells"] if c["rows"])
r=c["rows"][0]; cmd=m["replay"].replace("pneumachaos ", "", 1)+" --replay %s:%s" % (c["point"], r[m["columns"].index("repeat")])
print(cmd, ",".join(r[2:]), sep="\t")' "$dir/report/report_data.js") || exit 1
again=$(cd "$dir" && eval "\"$cli\" $cmd" 2>&1 >/dev/null | awk 'NR > 1 {print $2}' | paste -sd,)
echo "replayed: $again"
[ "$again" = "$line" ] || { echo "FAIL: the replay command gave another run than runs.csv: $line"; exit 1; }
