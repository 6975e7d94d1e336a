#!/usr/bin/env bash
# Installs the Debian packages the build, tests and showcase need, when missing.
# Usage: tests/tools/deps.sh [web]   (xvfb: the teardown tests open a real raylib window; web: emscripten and headless
#        chromium for make web / make test-web, plus python3 for the loopback runner)
set -eu
pkgs="g++ clang libclang-rt-dev cmake pkg-config dpkg-dev glslang-tools libegl-dev libgles-dev libosmesa6-dev libgl-dev libx11-dev libxrandr-dev libxi-dev libxcursor-dev libxinerama-dev libxext-dev libxxf86vm-dev xvfb xauth"
[ "${1:-}" = web ] && pkgs="emscripten chromium python3"
missing=""
for p in $pkgs; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "deps: installing:$missing"
if [ "$(id -u)" != 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "deps: missing packages ($missing) and not root; install them and retry" >&2; exit 1; fi
else SUDO=; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq || $SUDO apt-get update
$SUDO apt-get install -y -qq --no-install-recommends $missing
