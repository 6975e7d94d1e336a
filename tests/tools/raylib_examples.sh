#!/usr/bin/env bash
# The examples as raylib's own (run by tests/run.sh; ends with "raylib_examples: N passed, M failed"):
#   conventions  per examples/*.c: name <module>_<name>.c, raylib's header block (title
#                "raylib [<module>] example - <name>", complexity, versions, license, copyright), the
#                same title in InitWindow, 800x450, a same-named 800x450 .png, at most MAX_LINES lines
#   api          every raylib/rlgl function the examples call is listed in tests/raylib_api_examples.txt
#                with a declaration identical to the raylib.h/rlgl.h built against (6.0); the list
#                records the one-off comparison with raylib master. RAYLIB_API_COMPARE=<raylib>/src
#                checks the list against another tree (how that comparison is repeated).
#   makefile     raylib 6.0's own examples/Makefile (tests/raylib_examples/Makefile, unmodified: its git
#                blob id is checked) builds the examples in a copy of raylib's layout (src/ with the
#                headers and libraylib.a, examples/), after the README's copy commands ran as printed
#   env: BUILD, RAYLIB_CFLAGS, RAYLIB_LIBS
set -u
BUILD=${BUILD:-build}
MAX_LINES=360       # "around 300": raylib 6.0's own longer ones: shaders_basic_pbr.c 352, shapes_rectangle_advanced.c 358
RAYLIB_60_MAKEFILE_BLOB=334f596946948cd7b05d9422bce51383f25884f4   # raylib tag 6.0 (dbc56a8), examples/Makefile
pass=0; fail=0
ok()  { echo "  ok    $*"; pass=$((pass + 1)); }
bad() { echo "  FAIL  $*"; fail=$((fail + 1)); }

# ---- conventions ---------------------------------------------------------------------------
png_size() { # width x height from the IHDR chunk, or nothing
  [ "$(od -An -tx1 -N8 "$1" 2>/dev/null | tr -d ' \n')" = 89504e470d0a1a0a ] || return
  od -An -tu1 -j16 -N8 "$1" | awk '{ printf "%dx%d", $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }'
}
for f in examples/*.c; do
  name=$(basename "$f" .c); module=${name%%_*}; why=""
  case $module in core|shapes|textures|text|models|shaders|audio) ;; *) why="$why; module '$module' is not one of raylib's" ;; esac
  echo "$name" | grep -qE '^[a-z]+_[a-z0-9_]+$' || why="$why; name is not <module>_<name> in lower case"
  title=$(sed -n 's/^\*   \(raylib \[[a-z]*\] example - .*\)$/\1/p' "$f" | head -1)
  [ "$title" = "${title#raylib \[$module\] example - }" ] && why="$why; no header title 'raylib [$module] example - ...'"
  head -1 "$f" | grep -q '^/\*\*\*\*\*\*\*\*\*\*' || why="$why; does not open with raylib's header block"
  for line in 'Example complexity rating: \[[★☆]{4}\] [1-4]/4' 'Example originally created with raylib [0-9.]+, last time updated with raylib [0-9.]+' \
              'Example licensed under an unmodified zlib/libpng license' 'Copyright \(c\) [0-9]{4}'; do
    grep -qE "^\*   $line" "$f" || why="$why; header lacks '$line'"
  done
  grep -qF "InitWindow(screenWidth, screenHeight, \"$title\");" "$f" || why="$why; InitWindow title is not the header's"
  grep -qE '^    const int screenWidth = 800;$' "$f" && grep -qE '^    const int screenHeight = 450;$' "$f" || why="$why; not 800x450"
  size=$(png_size "examples/$name.png"); [ "$size" = 800x450 ] || why="$why; examples/$name.png is '${size:-missing}', not 800x450"
  lines=$(wc -l < "$f"); [ "$lines" -le $MAX_LINES ] || why="$why; $lines lines (> $MAX_LINES)"
  if [ -z "$why" ]; then ok "$name: raylib example conventions ($lines lines, $size screenshot)"; else bad "$name:${why#;}"; fi
done

# ---- api -----------------------------------------------------------------------------------
inc=""; for w in $RAYLIB_CFLAGS; do case $w in -I*) [ -f "${w#-I}/raylib.h" ] && inc=${w#-I} ;; esac; done
[ -z "$inc" ] && [ -f /usr/include/raylib.h ] && inc=/usr/include
decls() { # one normalised line per RLAPI declaration
  cat "$@" 2>/dev/null | grep '^RLAPI' | sed 's|//.*||; s/;.*$/;/; s/[[:space:]]\{1,\}/ /g; s/ *$//'
}
fname() { sed -E 's/^RLAPI .*[ *]([A-Za-z_][A-Za-z0-9_]*)\(.*/\1/'; }
list=tests/raylib_api_examples.txt
check_api() { # $1 = directory with raylib.h and rlgl.h, $2 = label
  local dir=$1 label=$2 why="" n=0
  if [ ! -f "$dir/raylib.h" ] || [ ! -f "$dir/rlgl.h" ]; then bad "api ($label): no raylib.h/rlgl.h in '$dir'"; return; fi
  local all; all=$(decls "$dir/raylib.h" "$dir/rlgl.h")
  local known; known=$(printf '%s\n' "$all" | fname | sort -u)
  local used; used=$(grep -ohE '\b[A-Za-z_][A-Za-z0-9_]*\(' examples/*.c | tr -d '(' | sort -u | comm -12 - <(printf '%s\n' "$known"))
  for fn in $used; do
    grep -qE "^RLAPI .*[ *]$fn\(" "$list" || why="$why; $fn is called but not in $list"
  done
  while IFS= read -r d; do
    n=$((n + 1))
    printf '%s\n' "$all" | grep -qxF -- "$d" || why="$why; differs or missing: $d"
    printf '%s\n' $used | grep -qxF -- "$(printf '%s\n' "$d" | fname)" || why="$why; listed but no longer called: $d"
  done < <(grep '^RLAPI' "$list")
  if [ -z "$why" ]; then ok "api ($label): $(echo $used | wc -w) raylib functions called, $n listed declarations identical in $dir"
  else bad "api ($label):${why#;}"; fi
}
check_api "$inc" "raylib built against"
[ -n "${RAYLIB_API_COMPARE:-}" ] && check_api "$RAYLIB_API_COMPARE" "RAYLIB_API_COMPARE"

# ---- makefile ------------------------------------------------------------------------------
mk=tests/raylib_examples/Makefile
root=$BUILD/raylib_examples/raylib
if [ "$(git hash-object "$mk" 2>/dev/null)" != $RAYLIB_60_MAKEFILE_BLOB ]; then
  bad "raylib examples Makefile: $mk is not raylib 6.0's examples/Makefile (blob $RAYLIB_60_MAKEFILE_BLOB)"
else
  rm -rf "$BUILD/raylib_examples"; mkdir -p "$root/src" "$root/examples/shaders"
  lib=""; for w in $RAYLIB_LIBS; do case $w in */libraylib.a) lib=$w ;; esac; done
  [ -n "$inc" ] && cp "$inc"/raylib.h "$inc"/rlgl.h "$inc"/raymath.h "$root/src/"
  [ -n "$lib" ] && cp "$lib" "$root/src/libraylib.a"
  cp "$mk" "$root/examples/Makefile"
  # The lib's platform: get-raylib.sh builds RGFW; a system raylib is raylib's default (GLFW)
  platform=PLATFORM_DESKTOP; [ -n "$lib" ] && nm "$lib" 2>/dev/null | grep -q ' T RGFW_' && platform=PLATFORM_DESKTOP_RGFW
  # The README's copy-and-build block as printed, with RAYLIB pointing at the copy of raylib's layout
  block=$(awk '/^<!-- tested by tests\/tools\/raylib_examples.sh -->$/ {m=1; next} m && /^```sh$/ {f=1; next} f && /^```$/ {exit} f' README.md | grep -v '^RAYLIB=')
  if [ -z "$block" ]; then bad "raylib examples Makefile: README has no copy block after the 'tested by' marker"
  elif out=$(RAYLIB=$(cd "$root" && pwd) PLATFORM=$platform bash -ec "$block" 2>&1); then
    built=""; missing=""
    for f in examples/*.c; do n=$(basename "$f" .c); if [ -x "$root/examples/${n%%_*}/$n" ]; then built="$built $n"; else missing="$missing $n"; fi; done
    if [ -z "$missing" ]; then ok "raylib 6.0 examples Makefile ($platform) built the README-copied examples:$built"
    else bad "raylib examples Makefile: not built:$missing"; printf '%s\n' "$out" | tail -10; fi
  else
    bad "raylib examples Makefile: the README's block failed"; printf '%s\n' "$out" | tail -15
  fi
fi

echo "raylib_examples: $pass passed, $fail failed"
