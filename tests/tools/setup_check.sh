#!/usr/bin/env bash
# Set-up checks (run by tests/run.sh; ends with "setup: N passed, M failed"):
#   messages     tests/tools/get-raylib.sh with no raylib anywhere, a too old pkg-config raylib, a
#                RAYLIB_SRC that is not a directory and one that holds raylib 5.5: exit 1, nothing on
#                stdout (build/raylib.mk stays unwritten), one failure message that says what was
#                found and the two ways to fix it (progress lines such as the Debian fetch may precede it)
#   header       rbillboard_lit.h against a raylib.h of version 5.5: one error, the header's own,
#                naming raylib 6.0
#   version      RBL_VERSION = MAJOR.MINOR.PATCH, the doc block, CHANGELOG.md and CMakeLists.txt agree
#   first try    a copy of the repository's tracked files (as a fresh clone), in a clean environment
#                (none of make test's variables), runs `make run
#                RAYLIB_SRC=<tree>` once and it succeeds: the tree is a stand-in raylib source whose
#                src/Makefile copies the libraylib.a the tests use (the Makefile and get-raylib.sh
#                are the real ones; only raylib's own compilation is skipped)
#   env: BUILD, RAYLIB_CFLAGS, RAYLIB_LIBS
set -u
BUILD=${BUILD:-build}
pass=0; fail=0
ok()  { echo "  ok    $*"; pass=$((pass + 1)); }
bad() { echo "  FAIL  $*"; fail=$((fail + 1)); }
work=$BUILD/setup_check; rm -rf "$work"; mkdir -p "$work"; work=$(cd "$work" && pwd)
root=$PWD
inc=""; for w in $RAYLIB_CFLAGS; do case $w in -I*) [ -f "${w#-I}/raylib.h" ] && inc=${w#-I} ;; esac; done
[ -z "$inc" ] && [ -f /usr/include/raylib.h ] && inc=/usr/include
lib=""; for w in $RAYLIB_LIBS; do case $w in */libraylib.a) lib=$w ;; esac; done

# A raylib 5.5 source tree: the real raylib.h with its version lines set back
mkdir -p "$work/raylib-5.5/src"
sed -e 's/^#define RAYLIB_VERSION_MAJOR .*/#define RAYLIB_VERSION_MAJOR 5/' -e 's/^#define RAYLIB_VERSION_MINOR .*/#define RAYLIB_VERSION_MINOR 5/' \
    -e 's/^#define RAYLIB_VERSION .*/#define RAYLIB_VERSION  "5.5"/' "$inc/raylib.h" > "$work/raylib-5.5/src/raylib.h"
cp "$inc/rlgl.h" "$inc/raymath.h" "$work/raylib-5.5/src/"

# No raylib anywhere: pkg-config and apt-get stand-ins that find nothing, an empty build folder
mkdir -p "$work/bin-none" "$work/bin-old"
printf '#!/bin/sh\nexit 1\n' > "$work/bin-none/pkg-config"
printf '#!/bin/sh\nexit 100\n' > "$work/bin-none/apt-get"
# A system raylib 5.5 (pkg-config answers 5.5, refuses >= 6.0)
printf '#!/bin/sh\ncase "$*" in *modversion*) echo 5.5 ;; *"raylib >= 6.0"*) exit 1 ;; *) exit 0 ;; esac\n' > "$work/bin-old/pkg-config"
cp "$work/bin-none/apt-get" "$work/bin-old/apt-get"
chmod +x "$work"/bin-*/*

# $1 label, $2 expected phrase (what was found); the rest: env assignments for get-raylib.sh
message_case() {
  local label=$1 found=$2; shift 2
  rm -rf "$work/b"; mkdir -p "$work/b"
  env "$@" BUILD="$work/b" bash tests/tools/get-raylib.sh > "$work/out.txt" 2> "$work/err.txt"; local rc=$?
  local why="" lines; lines=$(grep -c 'needs raylib 6.0 or later' "$work/err.txt")
  [ $rc = 1 ] || why="$why; exit $rc (not 1)"
  [ -s "$work/out.txt" ] && why="$why; printed make variables: $(head -c 200 "$work/out.txt")"
  [ "$lines" = 1 ] || why="$why; $lines failure messages (not one)"
  grep -qF -- "$found" "$work/err.txt" || why="$why; does not say '$found'"
  grep -qF 'make RAYLIB_SRC=' "$work/err.txt" || why="$why; no RAYLIB_SRC advice"
  grep -qF 'pkg-config' "$work/err.txt" || why="$why; no pkg-config advice"
  if [ -z "$why" ]; then ok "get-raylib, $label: one message ($(wc -l < "$work/err.txt") lines), says '$found' and how to fix it"
  else bad "get-raylib, $label:${why#;}"; sed 's/^/        /' "$work/err.txt"; fi
}
if [ -z "$inc" ]; then bad "setup: no raylib.h among RAYLIB_CFLAGS"; else
  message_case "no raylib anywhere" "pkg-config raylib: not found" PATH="$work/bin-none:$PATH" RAYLIB_SRC=
  message_case "pkg-config raylib 5.5" "version 5.5, older than 6.0" PATH="$work/bin-old:$PATH" RAYLIB_SRC=
  message_case "RAYLIB_SRC not a directory" "is not a directory" PATH="$work/bin-none:$PATH" RAYLIB_SRC="$work/no-such-raylib"
  message_case "RAYLIB_SRC holds raylib 5.5" "holds raylib 5.5" PATH="$work/bin-none:$PATH" RAYLIB_SRC="$work/raylib-5.5"

  # The header against raylib 5.5's version macros: its own error and nothing else
  for cc in cc c++; do
    x=c; [ $cc = c++ ] && x=c++
    $cc -x $x -fsyntax-only -Wall -Wextra -pedantic -I. -I"$work/raylib-5.5/src" -DCHECK_IMPLEMENTATION tests/compile_check.c > "$work/cc.txt" 2>&1
    rc=$?; errors=$(grep -c ': error:' "$work/cc.txt")
    if [ $rc != 0 ] && [ "$errors" = 1 ] && grep -q 'error:.*needs raylib 6.0 or later' "$work/cc.txt"; then
      ok "header ($cc) against raylib 5.5: one error: $(grep -o 'needs raylib 6.0 or later[^"]*' "$work/cc.txt" | head -1 | cut -c1-60)..."
    else bad "header ($cc) against raylib 5.5: exit $rc, $errors error lines"; head -8 "$work/cc.txt" | sed 's/^/        /'; fi
  done
fi

# One version everywhere: RBL_VERSION spells RBL_VERSION_MAJOR.MINOR.PATCH, the doc block's title and
# VERSIONS HISTORY name MAJOR.MINOR, CHANGELOG.md's newest entry is RBL_VERSION, CMakeLists.txt reads it
macro() { sed -n "s/^#define $1 *\([0-9][0-9]*\|\"[^\"]*\"\).*/\1/p" rbillboard_lit.h | head -1 | tr -d '"'; }
v=$(macro RBL_VERSION); mm="$(macro RBL_VERSION_MAJOR).$(macro RBL_VERSION_MINOR)"; why=""
[ -n "$v" ] && [ "$v" = "$mm.$(macro RBL_VERSION_PATCH)" ] || why="$why; RBL_VERSION '$v' is not MAJOR.MINOR.PATCH ($mm.$(macro RBL_VERSION_PATCH))"
grep -q "^\*   rbillboard_lit v$mm - " rbillboard_lit.h || why="$why; the doc block's title is not v$mm"
grep -q "^\*       $mm (" rbillboard_lit.h || why="$why; VERSIONS HISTORY has no $mm entry"
top=$(sed -n 's/^## \([0-9][0-9.]*\) .*/\1/p' CHANGELOG.md 2>/dev/null | head -1)
[ "$top" = "$v" ] || why="$why; CHANGELOG.md's newest entry is '$top', not $v"
grep -q 'REGEX "^#define RBL_VERSION \\""' CMakeLists.txt || why="$why; CMakeLists.txt does not read RBL_VERSION"
if [ -z "$why" ]; then ok "version $v: RBL_VERSION*, doc block title and history, CHANGELOG.md, CMakeLists.txt agree"
else bad "version:${why#;}"; fi

# First try in a fresh copy with RAYLIB_SRC (the issue: the recipe ran before raylib.mk's flags were read)
if [ -z "$lib" ] || [ -z "$inc" ]; then
  echo "  skip  first-try make run: raylib is not a libraylib.a here (pkg-config raylib); nothing to stand in with"
elif ! git rev-parse --git-dir >/dev/null 2>&1; then
  echo "  skip  first-try make run: not a git checkout (the copy is made of the tracked files)"
else
  mkdir -p "$work/raylib-stand-in/src" "$work/clone"
  cp "$inc/raylib.h" "$inc/rlgl.h" "$inc/raymath.h" "$work/raylib-stand-in/src/"
  printf 'all:\n\tcp %s $(RAYLIB_RELEASE_PATH)/libraylib.a\nclean:\n' "$lib" > "$work/raylib-stand-in/src/Makefile"
  git ls-files -z | xargs -0 cp --parents -t "$work/clone" 2>/dev/null
  if (cd "$work/clone" && env -u DISPLAY -u BUILD -u RAYLIB_CFLAGS -u RAYLIB_LIBS -u RAYLIB_MASTER -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
                                 make run RAYLIB_SRC="$work/raylib-stand-in") > "$work/first.txt" 2>&1 && [ -s "$work/clone/build/showcase.png" ]; then
    ok "first-try make run RAYLIB_SRC=<tree> in a fresh copy: $(grep -o 'showcase: wrote [^,]*' "$work/first.txt")"
  else bad "first-try make run RAYLIB_SRC=<tree> in a fresh copy"; tail -8 "$work/first.txt" | sed 's/^/        /'; fi
fi

echo "setup: $pass passed, $fail failed"
