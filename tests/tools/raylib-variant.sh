#!/usr/bin/env bash
# Builds raylib for another graphics API from the source tree get-raylib.sh used, once, into
# $BUILD/raylib-<variant>/ (libraylib.a + headers), for the GPU suite's other contexts:
#   es3   GRAPHICS_API_OPENGL_ES3, PLATFORM_MEMORY (no window system; link -lGLESv2)
#   es2   GRAPHICS_API_OPENGL_ES2, PLATFORM_MEMORY (link -lGLESv2)
#   gl21  GRAPHICS_API_OPENGL_21,  PLATFORM_MEMORY (link -lGL)
# The test harness makes the context itself (EGL), so raylib needs no platform layer. Built with
# SUPPORT_GPU_SKINNING=1 like the desktop library: compile against it with -DSUPPORT_GPU_SKINNING=1.
# Usage: tests/tools/raylib-variant.sh <es3|es2|gl21>
set -eu
BUILD=${BUILD:-build}
variant=$1
case $variant in
  es3) graphics=GRAPHICS_API_OPENGL_ES3 ;;
  es2) graphics=GRAPHICS_API_OPENGL_ES2 ;;
  gl21) graphics=GRAPHICS_API_OPENGL_21 ;;
  *) echo "raylib-variant: unknown variant $variant (es3, es2, gl21)" >&2; exit 1 ;;
esac
out=$BUILD/raylib-$variant
src=""
if [ -n "${RAYLIB_SRC:-}" ]; then src=$RAYLIB_SRC
elif [ -f "$BUILD/raylib/stamp" ]; then src=$(sed "s/ -D.*$//" "$BUILD/raylib/stamp")   # the stamp: source, then build flags
else src=$(ls -d "$BUILD"/raylib-src/raylib-*/ 2>/dev/null | head -1 || true); fi
src=${src%/}
if [ -z "$src" ] || [ ! -f "$src/src/raylib.h" ]; then
  echo "raylib-variant: no raylib source tree (a pkg-config raylib has none); set RAYLIB_SRC=<raylib source> to test $variant" >&2
  exit 1
fi
flags="-DSUPPORT_GPU_SKINNING=1"     # as the desktop build (get-raylib.sh): skinned Models on every API
stamp="$src $graphics $flags"
if [ -f "$out/libraylib.a" ] && [ "$(cat "$out/stamp" 2>/dev/null)" = "$stamp" ]; then exit 0; fi
echo "raylib-variant: building libraylib.a for $graphics (PLATFORM_MEMORY) from $src"
rm -rf "$out"; mkdir -p "$out"
# A private copy of src/: raylib's Makefile builds its objects in place
cp -r "$src/src" "$out/src"
make -s -C "$out/src" PLATFORM=PLATFORM_MEMORY GRAPHICS=$graphics RAYLIB_RELEASE_PATH="$(cd "$out" && pwd)" CUSTOM_CFLAGS="$flags" \
     RAYLIB_BUILD_MODE=RELEASE -j"$(nproc)" >"$out/build.log" 2>&1 \
  || { echo "raylib-variant: build failed, see $out/build.log" >&2; tail -20 "$out/build.log" >&2; exit 1; }
cp "$out/src/raylib.h" "$out/src/rlgl.h" "$out/src/raymath.h" "$out/"
rm -rf "$out/src"
echo "$stamp" > "$out/stamp"
