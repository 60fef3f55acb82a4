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
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
site="$build/docs-site"
"$repo/scripts/build-docs.sh" "$build" || exit 1
[ -f "$site/reference/cpp/html/index.html" ] || { echo "no C++ API pages (Doxygen)"; exit 1; }
"$here/docs_links.sh" "$site" || exit 1
"$here/docs_browser.sh" "$site/index.html" "$site"/guide/*.html
status=$?
[ "$status" -eq 0 ] && echo "docs site: built and checked"
exit "$status"

