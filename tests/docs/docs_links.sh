#!/usr/bin/env bash
# docs_links.sh SITE: every relative link and image of every HTML page under SITE resolves to a
# file, and every #anchor to an id in that page; no page loads a script, style or image from
# the network (the site must work offline). Doxygen's pages (reference/cpp) are left to Doxygen,
# and 404.html to a server (its links are from the server's root). Exit 1 naming each broken one.
set -uo pipefail
site=$(realpath "$1")
/usr/bin/python3 - "$site" <<'PY'
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
        if f.endswith(".html") and f != "404.html":  # 404.html is for a server: links from its root
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
exit $?
