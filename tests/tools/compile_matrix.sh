#!/usr/bin/env bash
# One cell of the language matrix tests/run.sh runs: compile and link one unit as C99 or C++11..23
# with -Wall -Wextra -pedantic -Werror -O1 (optimised: some warnings, -Wmaybe-uninitialized among them,
# only exist with the optimiser), writing "ok    <label>" or "FAIL  <label>" + the compiler's first
# lines to $3.
#   usage: compile_matrix.sh <compiler>:<std> <unit> <out-file> [<raylib tree>]
#   unit: header-decl | header-impl | header-options | readme | an example .c file
#   (header-options: the implementation with the optional module left out and the instruments in,
#   RBL_NO_ATLAS and RBL_INSTRUMENTS; header-impl has neither)
#   env:  BUILD, RAYLIB_CFLAGS, RAYLIB_LIBS
# With a raylib tree (another raylib's source, e.g. master), the unit is compiled against that tree's
# src/ headers only, with SUPPORT_GPU_SKINNING=1 (every path of the header), and not linked.
set -u
spec=$1 unit=$2 out=$3 other=${4:-}
cc=${spec%%:*} std=${spec#*:}
BUILD=${BUILD:-build}
lang=c; case $std in c++*) lang=c++ ;; esac
label="$cc -std=$std $unit"
if [ -n "$other" ]; then
  RAYLIB_CFLAGS="-I$other/src -DSUPPORT_GPU_SKINNING=1"
  label="$label against $(sed -n 's/^#define RAYLIB_VERSION *"\([^"]*\)".*/raylib \1/p' "$other/src/raylib.h" | head -1) ($other)"
fi
dir=$BUILD/tests/matrix; mkdir -p "$dir"
obj=$dir/$(echo "$cc-$std-$unit" | tr '/+.' '_px')

if ! command -v "$cc" >/dev/null 2>&1; then printf 'FAIL  %s (compiler not installed)\n' "$label" > "$out"; exit 0; fi
# clang 14 (Debian 12) knows C++23 as c++2b only
if [ "$std" = c++23 ] && ! echo 'int x;' | "$cc" -std=c++23 -x c++ -fsyntax-only - >/dev/null 2>&1; then
  std=c++2b; label="$label (as c++2b)"
fi
flags="-std=$std -x $lang -Wall -Wextra -pedantic -Werror -O1 -I. $RAYLIB_CFLAGS"
[ $lang = c ] && flags="$flags -D_DEFAULT_SOURCE"      # as the Makefile's C builds (clock_gettime etc.)
case $unit in
  header-decl) cmd="$cc $flags -c tests/compile_check.c -o $obj.o" ;;
  header-impl) cmd="$cc $flags -DCHECK_IMPLEMENTATION -c tests/compile_check.c -o $obj.o" ;;
  header-options) cmd="$cc $flags -DCHECK_IMPLEMENTATION -DRBL_NO_ATLAS -DRBL_INSTRUMENTS -c tests/compile_check.c -o $obj.o" ;;
  readme)      cmd="$cc $flags $BUILD/tests/readme_example.c -x none -o $obj $RAYLIB_LIBS" ;;
  *)           cmd="$cc $flags $unit -x none -o $obj $RAYLIB_LIBS" ;;
esac
# Another raylib's headers: compiled only (its libraylib.a is not built here)
[ -n "$other" ] && [ $unit != header-decl ] && [ $unit != header-impl ] && [ $unit != header-options ] && cmd="$cc $flags -c $unit -o $obj.o"
[ -n "$other" ] && [ $unit = readme ] && cmd="$cc $flags -c $BUILD/tests/readme_example.c -o $obj.o"
if log=$($cmd 2>&1); then printf 'ok    %s\n' "$label" > "$out"
else { printf 'FAIL  %s\n' "$label"; printf '%s\n' "$log" | head -12 | sed 's/^/        /'; } > "$out"; fi
rm -f "$obj" "$obj.o"
