#!/usr/bin/env bash
# docs_site.sh BUILD_DIR: builds the documentation site as a user would (scripts/build-docs.sh:
# every command of the guide runs, the reference is generated from the program, mkdocs
# --strict), then checks it as a reader would:
#   - every relative link and image of every page resolves to a file, and every #anchor to an
#     id in that file (Doxygen's own pages are left to Doxygen; their entry page must exist);
#   - the entry page and every guide page open in headless Chromium with no console message
#     and every image decoded (skipped, exit 77, where Chromium is missing).
set -uo pipefail
build=$(realpath "$1")
repo=$(cd "$(dirname "$0")/.." && pwd)
site="$build/docs-site"
"$repo/scripts/build-docs.sh" "$build" || exit 1
[ -f "$site/reference/cpp/html/index.html" ] || { echo "no C++ API pages (Doxygen)"; exit 1; }

/usr/bin/python3 - "$site" <<'PY' || exit 1
import html.parser, os, sys, urllib.parse
site = sys.argv[1]
class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.refs = set(), []
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a: self.ids.add(a["id"])
        if tag == "a" and "name" in a: self.ids.add(a["name"])
        for key in ("href", "src"):
            if a.get(key) and tag in ("a", "img", "link", "script"):
                self.refs.append((tag, a[key]))
pages = {}
for root, dirs, files in os.walk(site):
    if os.path.relpath(root, site).startswith(os.path.join("reference", "cpp")):
        continue
    for f in files:
        if f.endswith(".html"):
            p = Page(); p.feed(open(os.path.join(root, f), encoding="utf-8").read())
            pages[os.path.normpath(os.path.join(root, f))] = p
def ids_of(path):
    if path not in pages:
        p = Page(); p.feed(open(path, encoding="utf-8", errors="replace").read()); pages[path] = p
    return pages[path].ids
bad, checked = [], 0
for path, page in list(pages.items()):
    for tag, ref in page.refs:
        url = urllib.parse.urlparse(ref)
        if url.scheme or ref.startswith("//"):
            if url.scheme in ("http", "https") and tag != "a":
                bad.append(f"{path}: {tag} loads from the network: {ref}")
            continue
        checked += 1
        target = os.path.normpath(os.path.join(os.path.dirname(path), urllib.parse.unquote(url.path))) if url.path else path
        if not os.path.exists(target):
            bad.append(f"{os.path.relpath(path, site)}: {tag} -> {ref}: no such file")
        elif url.fragment and target.endswith(".html") and url.fragment not in ids_of(target):
            bad.append(f"{os.path.relpath(path, site)}: {ref}: no id '{url.fragment}' in {os.path.relpath(target, site)}")
print(f"links and images checked: {checked} in {len(pages)} pages, {len(bad)} broken")
for b in bad: print("  " + b)
sys.exit(1 if bad else 0)
PY

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
for page in "$site/index.html" "$site"/guide/*.html; do
  check="${page%.html}.check.html"
  # A copy beside the page, so relative links resolve the same; the checker writes into it.
  /usr/bin/python3 -c 'import sys; s = open(sys.argv[1]).read(); open(sys.argv[2], "w").write(s.replace("</body>", sys.argv[3] + "</body>"))' \
    "$page" "$check" "$script" || exit 1
  dom=$("$browser" --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
    --enable-logging=stderr --virtual-time-budget=10000 --dump-dom "file://$check" 2>"$check.log")
  result=$(grep -o 'checked images=[^<]*' <<<"$dom")
  opened=$((opened + 1))
  echo "${page#"$site/"}: ${result:-no result: the page did not finish loading}"
  if [ -z "$result" ] || ! grep -q "broken=0 " <<<"$result "; then fail=1; fi
  if grep -q "CONSOLE" "$check.log"; then
    echo "  console messages:"; grep "CONSOLE" "$check.log" | sed 's/^/  | /'; fail=1
  fi
  rm -f "$check" "$check.log"
done
[ "$fail" -eq 0 ] || exit 1
echo "docs site: built and checked, $opened pages opened in Chromium"
