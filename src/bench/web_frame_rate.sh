#!/usr/bin/env bash
# The browser build's figures in headless Chromium (SwiftShader's WebGL 2, 1280x720):
# the download size, and for each scene the time from the start of the page's load to
# its first frame and the frames per second over its first 6 s, real time. Needs
# `cmake --preset web && cmake --build --preset web` (build-web/site) and chromium.
# Usage: src/bench/web_frame_rate.sh [SITE_DIR] [scene query ...]
set -euo pipefail
site=${1:-build-web/site}
shift || true
queries=("$@")
[ ${#queries[@]} -gt 0 ] || queries=("scene=head_on" "scene=pile" "scene=pile&count=10000&radius=0.0232")
echo "download: $(du -cb "$site"/index.html "$site"/spheres.js "$site"/spheres.wasm | tail -1 | cut -f1) bytes"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
log=$(mktemp)
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site" 2>"$log" >/dev/null &
server=$!
profile=$(mktemp -d)
trap 'kill $server 2>/dev/null; rm -rf "$profile" "$log"' EXIT
sleep 1
for query in "${queries[@]}"; do
  : >"$log"
  timeout 40 chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
    --user-data-dir="$profile" --window-size=1280,720 "http://127.0.0.1:$port/index.html?$query&report" \
    >/dev/null 2>&1 &
  browser=$!
  for _ in $(seq 60); do grep -aq "GET /report" "$log" && break; sleep 0.5; done
  kill $browser 2>/dev/null || true
  wait $browser 2>/dev/null || true
  figures=$(grep -ao "GET /report?[^ ]*" "$log" | head -1 | sed 's/GET \/report?//; s/&/  /g' || true)
  echo "$query: ${figures:-no report within 30 s}"
done
