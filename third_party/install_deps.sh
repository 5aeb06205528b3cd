#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, and only those missing.
# Safe to run any number of times: it does nothing when everything is there.
#   --fuzz  also clang and its sanitizer and libFuzzer runtimes, for
#           src/tests/run_sanitized.sh (the test command asks for them)
#   --web   also emscripten (C++ to WebAssembly) and chromium (headless, to test the
#           page), for the browser build (src/web/)
#   --peers also Bullet and ODE, for the benchmark against them (spheres_bench_peers;
#           configure the build again afterwards so that CMake finds them)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config python3
  libglfw3-dev libglm-dev libimgui-dev libstb-dev python3-glad
  libosmesa6-dev libegl-dev libgl-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev
  fonts-dejavu-core xvfb xauth xdotool x11-xkb-utils
)
for option in "$@"; do
  case "$option" in
    --fuzz) packages+=(clang libclang-rt-14-dev) ;;
    --web) packages+=(emscripten chromium) ;;
    --peers) packages+=(libbullet-dev libode-dev) ;;
    *) echo "install_deps.sh: unknown option $option (known: --fuzz, --web, --peers)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install_deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
