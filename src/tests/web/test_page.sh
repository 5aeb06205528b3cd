#!/usr/bin/env bash
# The browser build against the desktop (issue 20): builds the web target with
# emscripten into BUILD (as `cmake --preset web` does), serves BUILD/site on a free
# local port, loads pages in headless Chromium and compares what each page exports
# (its <pre id="state">) with `spheres simulate` on the same scene, settings and steps:
# the same state hash, bit for bit, and the same energies. A link with a bad scene or
# setting must say why. The live view takes a link's settings, and its screenshot
# (SwiftShader's WebGL 2) shows the panel and the spheres; driven with real mouse and
# key events, it answers them as the window does. Exit 77 (ctest: skipped)
# without emscripten or chromium.
# Usage: test_page.sh SPHERES_EXECUTABLE SOURCE_DIR BUILD_DIR
set -euo pipefail
spheres=$1 source=$2 build=$3
if ! command -v emcmake >/dev/null || ! command -v chromium >/dev/null; then
  echo "skipped: emscripten or chromium is missing (third_party/install_deps.sh --web)"
  exit 77
fi
export NODE_PATH=/usr/share/nodejs  # emscripten's optimizer needs Debian's acorn
log=$(mktemp)
profile=$(mktemp -d)  # chromium's, for this run alone
results=$(mktemp -d)  # what each check said
if ! { cmake -S "$source" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
         -DCMAKE_TOOLCHAIN_FILE=/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake &&
       cmake --build "$build"; } >"$log" 2>&1; then
  tail -40 "$log"
  echo "the browser build failed (above)"
  exit 1
fi

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$build/site" >/dev/null 2>&1 &
server=$!
trap 'kill $server ${pids[*]:-} 2>/dev/null; wait 2>/dev/null; rm -rf "$profile" "$log" "$results" 2>/dev/null || true' EXIT
for _ in $(seq 50); do python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break; sleep 0.1; done

# The checks up to the driven page run in the background, two at a time: a headless
# Chromium keeps about one core busy, and its virtual clock now and then stalls for
# seconds. Each check prints its line and returns its verdict; the lines are printed in
# the order the checks were started, as soon as those before have finished (a run that
# hangs shows how far it got), and a check that failed fails the test.
checks=0 printed=0 pids=()
print_finished() {  # the finished checks' lines, in order, up to the first still running
  while [ "$printed" -lt "$checks" ] && [ -s "$results/$((printed + 1)).status" ]; do
    printed=$((printed + 1))
    cat "$results/$printed" 2>/dev/null || echo "check $printed said nothing"
    [ "$(cat "$results/$printed.status")" = ok ] || failed=1
  done
}
in_background() {
  while [ "$(jobs -rp | grep -cvx "$server" || true)" -ge 2 ]; do wait -n || true; print_finished; done
  checks=$((checks + 1))
  { if "$@" </dev/null >"$results/$checks" 2>&1; then echo ok; else echo failed; fi >"$results/$checks.status"; } &
  pids+=($!)
}
said_in_order() {
  wait "${pids[@]}" || true
  print_finished
}
# A profile of its own for each Chromium (two run at once), removed at the end.
new_profile() { mktemp -d -p "$profile"; }

# What the page at ?QUERY exports, as JSON text.
page() {
  { timeout 180 chromium --headless=new --no-sandbox --disable-gpu --user-data-dir="$(new_profile)" \
    --virtual-time-budget=120000 --dump-dom "http://127.0.0.1:$port/index.html?$1" 2>/dev/null || true; } |
    python3 -c 'import html, re, sys; m = re.search(r"<pre id=\"state\"[^>]*>([^<]*)</pre>", sys.stdin.read()); print(html.unescape(m.group(1)) if m else "")'
}

failed=0
# The run a link asks for (scene, steps, settings: name=value, space-separated) against
# `spheres simulate`'s.
same_state() {
  local scene=$1 steps=$2 settings=$3
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
  [ "$verdict" = same ]
}
# Listed spheres, a generated pile, settings from the link.
while read -r scene steps settings; do in_background same_state "$scene" "$steps" "$settings"; done <<'CASES'
08_newtons_cradle 600
03_head_on 600
02_bounce_projection 600
11_pile 600
cradle 600 beta=0.5 method=velocity
head_on 300 order=reversed passes=1
CASES

# Refused links: one line naming the problem, never a silent default.
refused() {
  said=$(page "$1")
  if [[ "$said" == *"$2"* ]]; then echo "$1: refused ($2)"; else echo "$1: not refused: $said"; return 1; fi
}
while read -r query expected; do in_background refused "$query" "$expected"; done <<'CASES'
scene=nosuch&steps=10 no such preset
scene=cradle&steps=10&beta=7 out of range
scene=cradle&steps=10&methd=velocity unknown parameter 'methd'
scene=cradle&steps=abc give a whole number of steps
scene=pile&steps=1&count=7483 holds only
scene=cradle&steps=10&compare=order=reversed compare: for the live view
CASES
# A browser without WebGL 2: the page says so in one line.
without_webgl() {
  said=$(timeout 180 chromium --headless=new --no-sandbox --disable-3d-apis --user-data-dir="$(new_profile)" \
    --virtual-time-budget=3000 --dump-dom "http://127.0.0.1:$port/index.html?scene=cradle" 2>/dev/null |
    grep -o 'class="error">Cannot run it: [^<]*' | sed 's/^class="error">//' || true)
  echo "no WebGL 2: ${said:-nothing said}"
  [ "$said" = "Cannot run it: this browser has no WebGL 2" ]
}
in_background without_webgl

# The live view's page at ?QUERY after 3 s of virtual time, as HTML text.
# Now and then Chromium's virtual clock stalls in a load: the page then runs on the real
# clock, for 7 to 30 s where a load takes 2. Such a load is given up after 15 s and tried
# again (its third try has the 180 s of the others).
live_dom() {
  local limit status dom
  for limit in 15 15 180; do
    status=0
    dom=$(timeout -k 5 "$limit" chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
      --user-data-dir="$(new_profile)" --virtual-time-budget=3000 --dump-dom "http://127.0.0.1:$port/index.html?$1" \
      2>/dev/null) || status=$?
    [ "$status" -eq 124 ] || [ "$status" -eq 137 ] || break  # 124, 137: timed out
  done
  printf '%s\n' "$dom"
}

# The live view (no steps in the link): it runs (its clock advanced), and the settings
# of the link took effect...
live_view_runs() {
  verdict=$(DOM="$(live_dom "scene=cradle&beta=0.5&method=velocity")" python3 -c '
import html, json, os, re
dom = os.environ["DOM"]
def exported(name):
    m = re.search(r"<pre id=\"%s\"[^>]*>([^<]*)</pre>" % name, dom)
    return json.loads(html.unescape(m.group(1)) or "null") if m else None
table = {p["name"]: p for p in exported("parameters") or []}
run = exported("state") or {}
method = table.get("method", {})
took = table.get("beta", {}).get("value") == 0.5 and method.get("choices", [None])[int(method.get("value", -1))] == "velocity"
live = re.search(r"<body[^>]*class=\"live\"", dom) is not None and run.get("time_s", 0) > 0
timeline = run.get("timeline", {})  # its frames kept for stepping back, the newest shown
kept = timeline.get("frames", 0) > 1 and timeline.get("cursor") == timeline.get("frames", 0) - 1
print("runs, took effect, keeps its frames" if took and live and kept else "live %s, time %s, beta %s, method %s, timeline %s" %
      (live, run.get("time_s"), table.get("beta", {}).get("value"), method.get("value"), timeline))')
  echo "live view, beta=0.5&method=velocity: $verdict"
  [ "$verdict" = "runs, took effect, keeps its frames" ]
}
in_background live_view_runs

# Prints "WHAT, QUERY: SAID" (and what was expected when it is not that); fails unless
# SAID is EXPECTED. Usage: said_as WHAT QUERY SAID EXPECTED
said_as() {
  if [ "$3" = "$4" ]; then echo "$1, $2: $3"; else echo "$1, $2: $3 (expected $4)"; return 1; fi
}

# Side by side: the link's compare=..., or else the scene's own, opens the views, each
# with its label; overrides the scene cannot take are refused in one line, one view left.
side_by_side() {
  said=$(DOM="$(live_dom "$1")" python3 -c '
import html, json, os, re
dom = os.environ["DOM"]
m = re.search(r"<pre id=\"state\"[^>]*>([^<]*)</pre>", dom)
run = json.loads(html.unescape(m.group(1)) or "{}") if m else {}
views = [" ".join(v["lines"][0].split()) for v in run.get("views", [])]
refusal = re.search(r"<p class=\"refusal\" id=\"refusal\">([^<]*)</p>", dom)
print(" | ".join(views) if views else html.unescape(refusal.group(1)) if refusal and refusal.group(1) else "nothing")')
  said_as "side by side" "$1" "$said" "$2"
}
while read -r query expected; do in_background side_by_side "$query" "$expected"; done <<'CASES'
scene=cradle&compare=order=reversed A order = index | B order = reversed
scene=shock_column A shock = off, passes = 1 | B shock = off, passes = 4 | C shock = on, passes = 1 | D shock = on, passes = 4
scene=cradle&compare=order=sideways Cannot compare: order=sideways: order = 'sideways' is not a choice; choices: index, reversed, shuffled, colored
CASES

# A live link with a setting the scene refuses opens the scene without it (the link's other
# settings taken, one that needs another beside it too), the refusal said in one line under
# the text (it had left the student on the front page); a refused colouring still said too.
live_link() {
  said=$(DOM="$(live_dom "$1")" python3 -c '
import html, json, os, re
dom = os.environ["DOM"]
def exported(name):
    m = re.search(r"<pre id=\"%s\"[^>]*>([^<]*)</pre>" % name, dom)
    return json.loads(html.unescape(m.group(1)) or "null") if m else None
table = {p["name"]: p for p in exported("parameters") or []}
def shown(name):
    p = table.get(name)
    return "-" if p is None else p["choices"][int(p["value"])] if p.get("choices") else "%g" % p["value"]
said = [html.unescape(m) for m in re.findall(r"<p class=\"refusal\" id=\"(?:link-)?refusal\">([^<]*)</p>", dom) if m]
# What the view refused is said right under the settings refused, under the text, in sight.
under = re.search(r"id=\"link-refusal\">[^<]*</p>\s*<p class=\"refusal\" id=\"refusal\">[^<]", dom) is not None
print("method %s, toi %s, beta %s: %s%s" % (shown("method"), shown("toi"), shown("beta"), " | ".join(said) or "nothing said",
                                            " (under the text)" if under else ""))')
  said_as "live link" "$1" "$said" "$2"
}
while read -r query expected; do in_background live_link "$query" "$expected"; done <<'CASES'
scene=cradle&beta=7&method=velocity method velocity, toi -, beta 1: The link's beta=7: beta = 7 is out of range [0, 1]: opened without it.
scene=cradle&method=continuous&toi=bisection&beta=7&color-by=foo method continuous, toi bisection, beta 1: The link's beta=7: beta = 7 is out of range [0, 1]: opened without it. | View: color-by foo: expected contact, speed, id or penetration (under the text)
scene=cradle&compare=order=sideways&overlay=bogus&select=9 method velocity, toi -, beta 1: Cannot compare: order=sideways: order = 'sideways' is not a choice; choices: index, reversed, shuffled, colored. View: no overlay 'bogus'; overlays: velocity, contacts, impulses, penetration, trails, graph. select=9: the scene has 5 spheres, numbered from 0 (under the text)
CASES

# What the view draws: the link's color-by=... and overlay=..., in the run's state, and what
# its legend says its colours are (the first line's words up to its colon or comma: the
# contact graph paints the spheres by level, so its line replaces the colouring's); an
# overlay it does not know is refused in one line.
look() {
  said=$(DOM="$(live_dom "$1")" python3 -c '
import html, json, os, re
dom = os.environ["DOM"]
m = re.search(r"<pre id=\"state\"[^>]*>([^<]*)</pre>", dom)
look = (json.loads(html.unescape(m.group(1)) or "{}") if m else {}).get("look", {})
refusal = re.search(r"<p class=\"refusal\" id=\"refusal\">([^<]*)</p>", dom)
legend = re.split(r"[:,]", look.get("legend", ""))[0]
print(html.unescape(refusal.group(1)) if refusal and refusal.group(1) else
      "%s: %s; legend: %s" % (look.get("color_by"), ", ".join(look.get("overlays", [])) or "none", legend))')
  said_as "look" "$1" "$said" "$2"
}
while read -r query expected; do in_background look "$query" "$expected"; done <<'CASES'
scene=cradle contact: none; legend: blue free
scene=shock_pyramid&color-by=speed&overlay=graph,velocity speed: velocity, graph; legend: velocity
scene=shock_pyramid&color-by=speed&overlay=graph speed: graph; legend: contact graph
scene=cradle&overlay=sparkles View: no overlay 'sparkles'; overlays: velocity, contacts, impulses, penetration, trails, graph
CASES

# The inspector: a link's select=N (as a click on the sphere) shows its numbers and, after
# its first contact, the slides' formulas with the numbers; a number the scene does not
# have is refused in one line.
inspector() {
  said=$(DOM="$(live_dom "$1")" python3 -c '
import html, json, os, re
dom = os.environ["DOM"]
m = re.search(r"<pre id=\"state\"[^>]*>([^<]*)</pre>", dom)
sphere = (json.loads(html.unescape(m.group(1)) or "{}") if m else {}).get("selected")
shown = re.search(r"<h2 id=\"inspected\">([^<]*)</h2>", dom)
refusal = re.search(r"<p class=\"refusal\" id=\"refusal\">([^<]*)</p>", dom)
if refusal and refusal.group(1):
    print(html.unescape(refusal.group(1)))
elif sphere:
    c = sphere["contacts"]
    explained = c.get("count", 0) >= 1 and any(line["kind"] == "formula" for line in c.get("lines", []))
    print("%s, %s" % (shown.group(1) if shown else "no inspector", "explained" if explained else "nothing explained"))
else:
    print("nothing selected")')
  said_as "inspector" "$1" "$said" "$2"
}
while read -r query expected; do in_background inspector "$query" "$expected"; done <<'CASES'
scene=cradle&select=1 Sphere #1, explained
scene=cradle&select=7 select=7: the scene has 5 spheres, numbered from 0
CASES

# ...and its screenshot shows the panel (dark, on the left) and the spheres (coloured,
# in the view): not a blank page. It is kept as BUILD/page.png (the README's picture).
rm -f "$build/page.png" "$build/page_side_by_side.png"  # never an earlier run's
shoot() {
  timeout 180 chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
    --user-data-dir="$(new_profile)" --virtual-time-budget=3000 --window-size=1280,720 \
    --screenshot="$1" "http://127.0.0.1:$port/index.html?$2" >/dev/null 2>&1 || true
}
# What a screenshot shows: PNG FILE single|side -> "panel and spheres" (and "in both
# views" side by side), or what is missing.
looks="$results/looks.py"
cat >"$looks" <<'PY'
import struct, sys, zlib
import os
data = open(sys.argv[1], "rb").read() if os.path.exists(sys.argv[1]) else b""
if data[:8] != b"\x89PNG\r\n\x1a\n":
    print("no screenshot"); raise SystemExit
chunks, at = {}, 8
while at < len(data):
    length, kind = struct.unpack(">I4s", data[at:at + 8])
    chunks.setdefault(kind, []).append(data[at + 8:at + 8 + length])
    at += 12 + length
width, height, depth, colour = struct.unpack(">IIBB", chunks[b"IHDR"][0][:10])
channels = {2: 3, 6: 4}[colour]
raw, stride, rows, previous = zlib.decompress(b"".join(chunks[b"IDAT"])), width * channels, [], bytearray(width * channels)
for y in range(height):  # PNG's row filters
    kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - channels] if i >= channels else 0
        b, c = previous[i], previous[i - channels] if i >= channels else 0
        if kind == 1: line[i] = (line[i] + a) & 255
        elif kind == 2: line[i] = (line[i] + b) & 255
        elif kind == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif kind == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line); previous = line
def share(x0, x1, test, y0=0):
    hits = total = 0
    for y in range(y0, height, 4):
        for x in range(x0, x1, 4):
            px = rows[y][x * channels:x * channels + 3]; total += 1; hits += test(px)
    return hits / max(total, 1)
coloured = lambda p: max(p) - min(p) > 60
panel = share(5, 300, lambda p: max(p) < 21)  # the panel's #0f1013, darker than the page's #16181d
spheres = share(420, width, coloured)
verdict = "panel and spheres" if panel > 0.5 and spheres > 0.002 else "blank or broken: panel %.3f, spheres %.4f" % (panel, spheres)
if sys.argv[2] == "side":  # the canvas from x = 384 (24rem): two columns, a 4 px dark gap between
    middle = (384 + width) // 2
    left, right = share(384, middle - 8, coloured, 200), share(middle + 8, width, coloured, 200)
    gap = share(middle - 1, middle + 1, lambda p: max(p) < 40, 200)
    both = left > 0.002 and right > 0.002 and gap > 0.9
    verdict += " in both views" if both else ", not two views: spheres %.4f and %.4f, gap %.2f" % (left, right, gap)
print(verdict)
PY
# Usage: screenshot_shows WHAT FILE QUERY single|side EXPECTED
screenshot_shows() {
  shoot "$2" "$3"
  said_as "$1" "screenshot" "$(python3 "$looks" "$2" "$4")" "$5"
}
in_background screenshot_shows "live view" "$build/page.png" "scene=cradle" single "panel and spheres"
# Side by side (the cradle and its reversed order): spheres in both columns of the canvas.
in_background screenshot_shows "live view side by side" "$build/page_side_by_side.png" \
  "scene=cradle&compare=order=reversed" side "panel and spheres in both views"
said_in_order

# The live page driven with real mouse and key events (src/tests/web/drive_page.mjs): a
# click selects, typed numbers move a sphere, Ctrl+drag throws, F shoots, Esc, ←, P, R;
# the scene's text measured, and an invariant alarm. Alone: it waits on the real clock.
# A profile of its own (a Chromium of the checks above may still be writing its own: removing
# them all here failed once, "Directory not empty").
if ! timeout 200 node "$source/src/tests/web/drive_page.mjs" "http://127.0.0.1:$port/index.html" "$(new_profile)"; then
  echo "the live page, driven: failed (above)"
  failed=1
fi
exit $failed
