#!/usr/bin/env bash
# report_browser.sh CLI ROWS: writes a quick report and opens it in headless Chromium, as a
# reader would: no console message, every image decodes, the claims table has ROWS rows.
# Exits 77 (CTest's SKIP_RETURN_CODE) when Chromium is not installed.
set -uo pipefail
cli=$1 rows=$2
browser=$(command -v chromium || command -v chromium-browser) || {
  echo "SKIP: chromium is not installed (scripts/setup.sh installs it)"
  exit 77
}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$cli" reproduce --quick --out "$dir/report" >/dev/null || exit 1
# The checker is the report's own page with a script appended that writes what it found
# into the page (a copy beside index.html, so every relative link resolves the same way).
script=$(cat <<'JS'
<pre id="check">pending</pre><script>
window.addEventListener('load', () => {
  // The load event waits for every image; a broken one is complete with no natural size.
  const imgs = [...document.images];
  const bad = imgs.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src'));
  // The claims table is the page's first; the paper's judge's table of chaos rows follows it.
  const rows = document.querySelector('table').querySelectorAll('tr').length - 1;
  document.getElementById('check').textContent = 'checked' +
    ` images=${imgs.length} broken=${bad.length} rows=${rows} ${bad.join(' ')}`;
});
</script>
JS
)
python3 -c 'import sys; p=sys.argv[1]; s=open(p+"/index.html").read(); open(p+"/check.html","w").write(s.replace("</body>", sys.argv[2]+"</body>"))' "$dir/report" "$script" || exit 1
dom=$("$browser" --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
  --enable-logging=stderr --virtual-time-budget=15000 --dump-dom "file://$dir/report/check.html" \
  2>"$dir/log")
result=$(grep -o 'checked images=[^<]*' <<<"$dom")
echo "${result:-no result: the checker page did not finish}"
fail=0
[ -n "$result" ] || fail=1
grep -q "broken=0 " <<<"$result" || fail=1
grep -q "images=0 " <<<"$result" && fail=1
grep -q "rows=$rows " <<<"$result" || { echo "expected $rows claims"; fail=1; }
if grep -q "CONSOLE" "$dir/log"; then
  echo "console messages:"; grep "CONSOLE" "$dir/log"; fail=1
fi
exit $fail
