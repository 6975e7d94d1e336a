#!/usr/bin/env bash
# Builds raylib 6.0 for the browser with Debian's emscripten, once per graphics API:
#   tests/tools/get-raylib-web.sh es3|es2   ->  $BUILD/web/raylib-<api>/libraylib.web.a (+ headers)
# PLATFORM_WEB_RGFW: raylib's GLFW web platform does not build with Debian's emscripten 3.1.6.
# The source is the tree get-raylib.sh found (RAYLIB_SRC, else $BUILD/raylib-src/raylib-*), copied
# first so that the shared tree is never built in.
set -eu
BUILD=${BUILD:-build}
api=${1:?usage: get-raylib-web.sh es3|es2}
case $api in es3) graphics=GRAPHICS_API_OPENGL_ES3 ;; es2) graphics=GRAPHICS_API_OPENGL_ES2 ;;
  *) echo "get-raylib-web: unknown api $api (es3|es2)" >&2; exit 1 ;; esac
log() { echo "get-raylib-web: $*" >&2; }
command -v emcc >/dev/null || { log "emcc missing (run tests/tools/deps.sh web)"; exit 1; }
src=${RAYLIB_SRC:-}
[ -n "$src" ] || src=$(ls -d "$BUILD"/raylib-src/raylib-*/ 2>/dev/null | head -1 || true)
[ -n "$src" ] && [ -f "$src/src/raylib.h" ] || { log "no raylib source tree (make test fetches it into $BUILD/raylib-src)"; exit 1; }
src=$(cd "$src" && pwd)
out=$BUILD/web/raylib-$api
flags="-DSUPPORT_GPU_SKINNING=1"     # as get-raylib.sh: the skinned-model tests need raylib's GPU bone path
if [ -f "$out/libraylib.web.a" ] && [ "$(cat "$out/stamp" 2>/dev/null)" = "$src $graphics $flags" ]; then exit 0; fi
log "building raylib for PLATFORM_WEB_RGFW $graphics ($flags) from $src"
rm -rf "$out"; mkdir -p "$out"
cp -r "$src/src" "$out/src"
# Debian's emscripten finds its JS tools' modules only through NODE_PATH
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
make -s -C "$out/src" PLATFORM=PLATFORM_WEB_RGFW GRAPHICS=$graphics RAYLIB_BUILD_MODE=RELEASE CUSTOM_CFLAGS="$flags" \
     RAYLIB_RELEASE_PATH="$(cd "$out" && pwd)" RAYLIB_MODULE_AUDIO=FALSE -j2 >"$out/build.log" 2>&1 \
  || { log "raylib web build failed, see $out/build.log"; tail -20 "$out/build.log" >&2; exit 1; }
cp "$out/src/raylib.h" "$out/src/rlgl.h" "$out/src/raymath.h" "$out/"
rm -rf "$out/src"
echo "$src $graphics $flags" > "$out/stamp"
