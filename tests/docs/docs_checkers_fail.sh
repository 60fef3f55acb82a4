#!/usr/bin/env bash
# docs_checkers_fail.sh: the documentation checkers must fail where they should. A two-page
# site with a missing page, a missing anchor, a script from the network, an image that does
# not exist and a console error: docs_links.sh must name the first three, docs_browser.sh
# must fail on the last two; the same site repaired must pass both.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
site=$(mktemp -d)
trap 'rm -rf "$site"' EXIT
cat >"$site/index.html" <<'HTML'
<html><body><h1 id="top">t</h1><a href="other.html#top">ok</a><a href="gone.html">gone</a>
<a href="other.html#nowhere">anchor</a><script src="https://cdn.example/x.js"></script>
<img src="missing.png"><script>console.error("boom")</script></body></html>
HTML
echo '<html><body><h1 id="top">o</h1><a href="index.html#top">back</a></body></html>' >"$site/other.html"
fail=0
out=$("$here/docs_links.sh" "$site") && { echo "docs_links.sh passed a broken site"; fail=1; }
for expect in "gone.html: no such file" "no id 'nowhere'" "loads from the network" "missing.png: no such file"; do
  grep -qF "$expect" <<<"$out" || { echo "docs_links.sh did not report: $expect"; fail=1; }
done
out=$("$here/docs_browser.sh" "$site/index.html")
status=$?
if [ "$status" -ne 77 ]; then
  [ "$status" -eq 1 ] || { echo "docs_browser.sh passed a broken page"; fail=1; }
  grep -q "broken=1 missing.png" <<<"$out" || { echo "docs_browser.sh did not report the image"; fail=1; }
  grep -q '"boom"' <<<"$out" || { echo "docs_browser.sh did not report the console error"; fail=1; }
fi
# Repaired, both pass: the failures above came from the breakage, not from the checkers.
echo '<html><body><h1 id="top">t</h1><a href="other.html#top">ok</a></body></html>' >"$site/index.html"
"$here/docs_links.sh" "$site" >/dev/null || { echo "docs_links.sh failed a sound site"; fail=1; }
"$here/docs_browser.sh" "$site/index.html" >/dev/null
status=$?
[ "$status" -eq 0 ] || [ "$status" -eq 77 ] || { echo "docs_browser.sh failed a sound page"; fail=1; }
[ "$fail" -eq 0 ] && echo "the checkers fail on each breakage and pass the repaired site"
exit "$fail"
