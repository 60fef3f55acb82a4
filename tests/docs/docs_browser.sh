#!/usr/bin/env bash
# docs_browser.sh PAGE.html...: opens each page in headless Chromium as a reader would; fails
# when a page does not finish loading, logs a console message, or has an image that does not
# decode. Exits 77 (CTest's SKIP_RETURN_CODE) when Chromium is not installed.
set -uo pipefail
browser=$(command -v chromium || command -v chromium-browser) || {
  echo "SKIP: chromium is not installed (scripts/setup.sh installs it)"; exit 77; }
script='<pre id="doccheck">pending</pre><script>
window.addEventListener("load", () => {
  const imgs = [...document.images];
  const bad = imgs.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute("src"));
  document.getElementById("doccheck").textContent =
    `checked images=${imgs.length} broken=${bad.length} ${bad.join(" ")}`;
});
</script>'
fail=0 opened=0
for page in "$@"; do
  check="${page%.html}.check.html"
  # A copy beside the page, so relative links resolve the same; the checker writes into it.
  /usr/bin/python3 -c 'import sys; s = open(sys.argv[1]).read(); open(sys.argv[2], "w").write(s.replace("</body>", sys.argv[3] + "</body>"))' \
    "$page" "$check" "$script" || exit 1
  dom=$("$browser" --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
    --enable-logging=stderr --virtual-time-budget=10000 --dump-dom "file://$check" 2>"$check.log")
  result=$(grep -o 'checked images=[0-9][^<]*' <<<"$dom")
  opened=$((opened + 1))
  echo "$(basename "$(dirname "$page")")/$(basename "$page"): ${result:-no result: the page did not finish loading}"
  if [ -z "$result" ] || ! grep -q "broken=0 " <<<"$result "; then fail=1; fi
  if grep -q "CONSOLE" "$check.log"; then
    echo "  console messages:"; grep "CONSOLE" "$check.log" | sed 's/^/  | /'; fail=1
  fi
  rm -f "$check" "$check.log"
done
[ "$fail" -eq 0 ] || exit 1
echo "opened in Chromium: $opened pages, no console message, every image decoded"
