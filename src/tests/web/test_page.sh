#!/usr/bin/env bash
# The browser build against the desktop (issue 20): builds the web target with
# emscripten into BUILD (as `cmake --preset web` does), serves BUILD/site on a free
# local port, loads pages in headless Chromium and compares what each page exports
# (its <pre id="state">) with `spheres simulate` on the same scene, settings and steps:
# the same state hash, bit for bit, and the same energies. A link with a bad scene or
# setting must say why. Exit 77 (ctest: skipped) without emscripten or chromium.
# Usage: test_page.sh SPHERES_EXECUTABLE SOURCE_DIR BUILD_DIR
set -euo pipefail
spheres=$1 source=$2 build=$3
if ! command -v emcmake >/dev/null || ! command -v chromium >/dev/null; then
  echo "skipped: emscripten or chromium is missing (third_party/install_deps.sh --web)"
  exit 77
fi
export NODE_PATH=/usr/share/nodejs  # emscripten's optimizer needs Debian's acorn
cmake -S "$source" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_TOOLCHAIN_FILE=/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake >/dev/null
cmake --build "$build" >/dev/null

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$build/site" >/dev/null 2>&1 &
server=$!
trap 'kill $server 2>/dev/null' EXIT
for _ in $(seq 50); do python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break; sleep 0.1; done

# What the page at ?QUERY exports, as JSON text.
page() {
  timeout 180 chromium --headless=new --no-sandbox --disable-gpu --user-data-dir="$build/chromium-profile" \
    --virtual-time-budget=120000 --dump-dom "http://127.0.0.1:$port/index.html?$1" 2>/dev/null |
    python3 -c 'import html, re, sys; m = re.search(r"<pre id=\"state\"[^>]*>([^<]*)</pre>", sys.stdin.read()); print(html.unescape(m.group(1)) if m else "")'
}

failed=0
# scene, steps, settings (name=value, space-separated): listed spheres, a generated pile, settings from the link.
while read -r scene steps settings; do
  query="scene=$scene&steps=$steps"
  sets=()
  for setting in $settings; do query+="&$setting"; sets+=(--set "$setting"); done
  native=$("$spheres" simulate --scene "$scene" --steps "$steps" "${sets[@]}" 2>/dev/null)
  web=$(page "$query")
  verdict=$(NATIVE="$native" WEB="$web" python3 - <<'PY'
import json, os, re
native, web = os.environ["NATIVE"], os.environ["WEB"]
if not web:
    print("the page exported nothing"); raise SystemExit
state = json.loads(web)
if "error" in state:
    print("the page says: " + state["error"]); raise SystemExit
want = {"hash": re.search(r"hash ([0-9a-f]{16})", native).group(1),
        "kinetic": re.search(r"E_kin (\S+) J", native).group(1),
        "potential": re.search(r"E_pot (\S+) J", native).group(1)}
got = {"hash": state["hash"], "kinetic": "%.6g" % state["kinetic_J"], "potential": "%.6g" % state["potential_J"]}
print("same" if want == got else "differs: desktop %s, page %s" % (want, got))
PY
)
  echo "$query: $verdict"
  [ "$verdict" = same ] || failed=1
done <<'CASES'
08_newtons_cradle 600
03_head_on 600
02_bounce_projection 600
11_pile 600
cradle 600 beta=0.5 method=velocity
head_on 300 order=reversed passes=1
CASES

# Refused links: one line naming the problem, never a silent default.
while read -r query expected; do
  said=$(page "$query")
  if [[ "$said" == *"$expected"* ]]; then echo "$query: refused ($expected)"; else echo "$query: not refused: $said"; failed=1; fi
done <<'CASES'
scene=nosuch&steps=10 no such preset
scene=cradle&steps=10&beta=7 out of range
scene=cradle&steps=10&methd=velocity methd
CASES
exit $failed
