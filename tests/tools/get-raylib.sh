#!/usr/bin/env bash
# Finds raylib >= 6.0 and prints the make variables to use it, one per line:
#   RAYLIB_CFLAGS=...   RAYLIB_LIBS=...
# Order: (1) system raylib via pkg-config, (2) RAYLIB_SRC=<raylib source tree>,
# (3) Debian's source package `raylib` (unstable) fetched with `apt-get source` through a
# private apt configuration that reuses this machine's own Debian URI (system sources untouched).
# (2) and (3) build libraylib.a once (PLATFORM_DESKTOP_RGFW, SUPPORT_GPU_SKINNING=1 for the skinned
# lit programs) into $BUILD/raylib and reuse it; the stamp records the source and the flags, so a
# build made with other flags is rebuilt. Their RAYLIB_CFLAGS pass SUPPORT_GPU_SKINNING=1 on to the
# header (a pkg-config raylib says nothing: the header assumes no GPU skinning).
set -eu
BUILD=${BUILD:-build}
mkdir -p "$BUILD"
BUILD=$(cd "$BUILD" && pwd)
log() { echo "get-raylib: $*" >&2; }
# One message for every way of not finding raylib: what was found, then what to do; exit 1
fail() {
  { echo "get-raylib: $1."
    [ -n "${2:-}" ] && printf '%s\n' "$2" | sed 's/^/    /'
    echo "  rbillboard_lit needs raylib 6.0 or later. Either point the build at a raylib source tree:"
    echo "    git clone --depth 1 --branch 6.0 https://github.com/raysan5/raylib ../raylib && make RAYLIB_SRC=../raylib"
    echo "  or install raylib 6.0+ where pkg-config finds it (raylib.pc on PKG_CONFIG_PATH) and run make without RAYLIB_SRC."
  } >&2
  exit 1
}
tried=""
syslibs="-lGL -lX11 -lXrandr -lXi -lXcursor -lXext -lXinerama -lm -lpthread -ldl"

# (1) a system raylib
if [ -z "${RAYLIB_SRC:-}" ] && pkg-config --exists 'raylib >= 6.0' 2>/dev/null; then
  echo "RAYLIB_CFLAGS=$(pkg-config --cflags raylib)"
  echo "RAYLIB_LIBS=$(pkg-config --libs --static raylib)"
  exit 0
fi
pc=$(pkg-config --modversion raylib 2>/dev/null || true)
tried="$tried\n  - pkg-config raylib: ${pc:+version $pc, older than 6.0}${pc:-not found}"

build_from() { # $1 = source tree root (holds src/raylib.h)
  local src=$1 out=$BUILD/raylib flags="-DSUPPORT_GPU_SKINNING=1"
  if [ -f "$out/libraylib.a" ] && [ -f "$out/stamp" ] && [ "$(cat "$out/stamp")" = "$src $flags" ]; then :; else
    log "building libraylib.a from $src (PLATFORM_DESKTOP_RGFW, $flags)"
    rm -rf "$out"; mkdir -p "$out"
    # A private copy of src/: raylib's Makefile builds its objects in place, and its `clean` would
    # take the caller's own libraylib.a with them
    cp -r "$src/src" "$out/src"
    make -s -C "$out/src" PLATFORM=PLATFORM_DESKTOP_RGFW RAYLIB_RELEASE_PATH="$out" CUSTOM_CFLAGS="$flags" \
         RAYLIB_BUILD_MODE=RELEASE -j"$(nproc)" >"$out/build.log" 2>&1 \
      || { log "building raylib from $src failed; the end of $out/build.log:"; tail -20 "$out/build.log" | sed 's/^/    /' >&2
           log "missing system headers are installed by tests/tools/deps.sh (run as root, or with sudo)"; exit 1; }
    cp "$out/src/raylib.h" "$out/src/rlgl.h" "$out/src/raymath.h" "$out/"
    rm -rf "$out/src"
    echo "$src $flags" > "$out/stamp"
  fi
  echo "RAYLIB_CFLAGS=-I$out $flags"
  echo "RAYLIB_LIBS=$out/libraylib.a $syslibs"
}

version_ok() { # raylib.h declares RAYLIB_VERSION_MAJOR
  local maj; maj=$(sed -n 's/^#define RAYLIB_VERSION_MAJOR *\([0-9]*\).*/\1/p' "$1/src/raylib.h" 2>/dev/null)
  [ -n "$maj" ] && [ "$maj" -ge 6 ]
}
version_of() { # "raylib 5.5" or "no src/raylib.h"
  local v; v=$(sed -n 's/^#define RAYLIB_VERSION *"\([^"]*\)".*/\1/p' "$1/src/raylib.h" 2>/dev/null | head -1)
  if [ -n "$v" ]; then echo "raylib $v"; elif [ -f "$1/src/raylib.h" ]; then echo "a raylib.h without RAYLIB_VERSION"; else echo "no src/raylib.h"; fi
}

# (2) a source tree named by the caller
if [ -n "${RAYLIB_SRC:-}" ]; then
  src=$(cd "$RAYLIB_SRC" 2>/dev/null && pwd) || fail "RAYLIB_SRC=$RAYLIB_SRC is not a directory"
  version_ok "$src" || fail "RAYLIB_SRC=$src holds $(version_of "$src"), not raylib 6.0 or later"
  build_from "$src"; exit $?
fi
tried="$tried\n  - RAYLIB_SRC: not set"

# (3) Debian's source package, through a private apt configuration
fetch=$BUILD/raylib-src
existing=$(ls -d "$fetch"/raylib-*/ 2>/dev/null | head -1 || true)
if [ -n "$existing" ] && version_ok "$existing"; then build_from "${existing%/}"; exit $?; fi

# This machine's own Debian archive URI (deb822 .sources or one-line .list), never a typed-in host.
uri=$( { cat /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '
           /^URIs:/ {u=$2} /^Suites:/ {s=$0} /^$/ {if (u!="" && s !~ /security/) {print u; exit} u=""; s=""}
           END {if (u!="" && s !~ /security/) print u}';
         cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
           awk '$1=="deb" && $0 !~ /security/ { for (i=2;i<=NF;i++) if ($i ~ /^[a-z]+:\/\//) {print $i; exit} }'; } | head -1)
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
if [ -n "$uri" ] && [ -f "$keyring" ] && command -v apt-get >/dev/null; then
  command -v dpkg-source >/dev/null || { log "dpkg-dev is needed for apt-get source (run tests/tools/deps.sh)"; }
  apt=$BUILD/apt; mkdir -p "$apt/lists/partial" "$apt/archives/partial" "$fetch"
  echo "deb-src [signed-by=$keyring] $uri sid main" > "$apt/sources.list"
  opts="-o Dir::Etc::sourcelist=$apt/sources.list -o Dir::Etc::sourceparts=- -o Dir::State::Lists=$apt/lists -o Dir::Cache=$apt -o APT::Get::List-Cleanup=0"
  log "fetching Debian source package raylib (sid) via this machine's apt URI"
  if apt-get $opts update -qq >"$apt/update.log" 2>&1 &&
     (cd "$fetch" && apt-get $opts source -qq raylib >"$apt/source.log" 2>&1); then
    existing=$(ls -d "$fetch"/raylib-*/ 2>/dev/null | head -1 || true)
    if [ -n "$existing" ] && version_ok "$existing"; then build_from "${existing%/}"; exit $?; fi
    tried="$tried\n  - Debian source package raylib (sid): fetched, but not version >= 6.0"
  else
    tried="$tried\n  - Debian source package raylib (sid) via $uri: apt-get failed (see $apt/*.log)"
  fi
else
  tried="$tried\n  - Debian source package: no Debian source URI / keyring / apt-get on this machine"
fi

fail "no raylib 6.0 or later found; tried" "$(printf '%b' "$tried" | sed '/^$/d; s/^  - //')"
