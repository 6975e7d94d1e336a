#!/usr/bin/env bash
# Runs every test suite and prints one closing line "N passed, N failed" (exit 1 on any failure).
#   language matrix: the header (with and without the implementation), the README's code and every
#                   example as C99 (gcc, clang) and C++11/17/20/23 (g++, clang++), -Wall -Wextra -pedantic -Werror
#   master:         (optional) the header, README code and examples against raylib master's headers
#   cmake:          the README's CMake blocks as printed, and tests/cmake_consumer through
#                   add_subdirectory and FetchContent, built and run
#   setup:          missing/too old raylib messages, a fresh copy's first make run RAYLIB_SRC=<tree>
#   raylib_examples: the examples' raylib conventions, API list, build by raylib 6.0's examples Makefile
#   cpu:            geometry and shader-source tests (plain, then under ASan+UBSan)
#   api_san:        the 1.0 API tests (ownership, raylib-habitual unloads) under ASan+UBSan+LSan
#   contracts:      every public function x every class of bad input, one process per case (ASan+UBSan)
#   alloc:          RBL_MALLOC family failing at the Nth call, swept over N on every allocating path
#   teardown:       unloads, RblClose and CloseWindow in all six orders (C, C++ RAII), real window on xvfb
#   fuzz:           the atlas readers under libFuzzer (one target per format, bounded time)
#   gpu:            render tests under EGL surfaceless, then under OSMesa (GL 3.3 core), then on
#                   strict ES 3.0, ES 2.0 and GL 2.1 contexts with raylib built for each
#   web:            the browser subset in headless Chromium (make test-web alone runs just this)
#   page:           the showcase page and the README's web shell in headless Chromium (make test-page)
set -u
BUILD=${BUILD:-build}
pass=0; fail=0
count() { # $1 = suite output; adds its "suite: N passed, M failed" line
  local line; line=$(printf '%s\n' "$1" | grep -E '^[a-z][a-z0-9_-]*: [0-9]+ passed, [0-9]+ failed$' | tail -1)
  if [ -z "$line" ]; then echo "  FAIL  suite did not finish (no summary line)"; fail=$((fail + 1)); return; fi
  local p f; p=$(echo "$line" | sed -E 's/.*: ([0-9]+) passed.*/\1/'); f=$(echo "$line" | sed -E 's/.* ([0-9]+) failed$/\1/')
  pass=$((pass + p)); fail=$((fail + f))
}

# The language matrix: the header (declarations; implementation), the README's code and every
# example compile (and, but for the header checks, link) as C99 with gcc and clang and as C++11, 17,
# 20 and 23 with g++ and clang++, -Wall -Wextra -pedantic -Werror -O1; two cells at a time
# (tests/tools/compile_matrix.sh, one cell each).
# The README's code is extracted as printed: the first ```c block is the drop-in program; every
# later block is a snippet, compiled as the body of a function given a `Model model` and a `Camera3D camera`
echo "== language matrix (C99, C++11/17/20/23; gcc, clang, g++, clang++)"
mkdir -p "$BUILD/tests/matrix"
awk '/^```c$/{n++; f=1; if (n > 1) print "void readme_snippet_" n "(Model model, Camera3D camera);\nvoid readme_snippet_" n "(Model model, Camera3D camera)\n{\n(void)model; (void)camera;"; next}
     /^```$/{ if (f && n > 1) print "}"; f=0; next } f' README.md > "$BUILD/tests/readme_example.c"
readme_blocks=$(grep -c '^```c$' README.md)
if [ "$readme_blocks" -ge 1 ]; then echo "  ok    README: $readme_blocks c blocks extracted"; pass=$((pass + 1))
else echo "  FAIL  README: no c block extracted"; fail=$((fail + 1)); fi
jobs=""; n=0
for unit in header-decl header-impl readme examples/*.c; do
  for spec in gcc:c99 clang:c99 g++:c++11 g++:c++17 g++:c++20 g++:c++23 clang++:c++11 clang++:c++17 clang++:c++20 clang++:c++23; do
    n=$((n + 1)); jobs="$jobs$spec $unit $BUILD/tests/matrix/cell$n.txt
"
  done
done
# The options (RBL_NO_ATLAS, RBL_INSTRUMENTS) once in C and once in C++
for spec in gcc:c99 g++:c++11; do n=$((n + 1)); jobs="$jobs$spec header-options $BUILD/tests/matrix/cell$n.txt
"; done
rm -f "$BUILD"/tests/matrix/cell*.txt
printf '%s' "$jobs" | BUILD=$BUILD RAYLIB_CFLAGS="$RAYLIB_CFLAGS" RAYLIB_LIBS="$RAYLIB_LIBS" xargs -P 2 -L 1 bash tests/tools/compile_matrix.sh
for i in $(seq 1 $n); do
  f=$BUILD/tests/matrix/cell$i.txt
  if [ -s "$f" ] && head -1 "$f" | grep -q '^ok '; then pass=$((pass + 1)); sed 's/^/  /' "$f"
  else fail=$((fail + 1)); if [ -s "$f" ]; then sed 's/^/  /' "$f"; else echo "  FAIL  matrix cell $i (no result)"; fi; fi
done

# raylib master (6.1-dev) renames things add-ons touch: the header, the README's code and every
# example compile against its headers (not linked) when a tree is at hand: RAYLIB_MASTER=<raylib
# source tree>, else $BUILD/raylib-master (`make raylib-master` clones it). Without one (CI has no
# network) the check is skipped with one line and counted neither way.
echo "== raylib master headers (optional)"
master=${RAYLIB_MASTER:-$BUILD/raylib-master}
if [ -f "$master/src/raylib.h" ]; then
  master=$(cd "$master" && pwd); jobs=""; n=0
  for unit in header-impl readme examples/*.c; do
    for spec in gcc:c99 clang:c99 g++:c++11 clang++:c++23; do
      n=$((n + 1)); jobs="$jobs$spec $unit $BUILD/tests/matrix/master$n.txt $master
"
    done
  done
  rm -f "$BUILD"/tests/matrix/master*.txt
  printf '%s' "$jobs" | BUILD=$BUILD RAYLIB_CFLAGS="$RAYLIB_CFLAGS" RAYLIB_LIBS="$RAYLIB_LIBS" xargs -P 2 -L 1 bash tests/tools/compile_matrix.sh
  for i in $(seq 1 $n); do
    f=$BUILD/tests/matrix/master$i.txt
    if [ -s "$f" ] && head -1 "$f" | grep -q '^ok '; then pass=$((pass + 1)); sed 's/^/  /' "$f"
    else fail=$((fail + 1)); if [ -s "$f" ]; then sed 's/^/  /' "$f"; else echo "  FAIL  master cell $i (no result)"; fi; fi
  done
else
  echo "  skip  no raylib master tree (RAYLIB_MASTER=<raylib source tree>, or make raylib-master, runs it)"
fi

# The README's API index and the doc block's CONFIGURATION list against the header
echo "== test-lists (each GPU test registered beside its body)"
out=$(python3 tests/tools/test_lists.py check 2>&1); printf '%s\n' "$out"; count "$out"
out=$(python3 tests/tools/align_comments.py check 2>&1); printf '%s\n' "$out"; count "$out"
echo "== api (README index, CONFIGURATION)"
out=$(bash tests/tools/api_index.sh check rbillboard_lit.h README.md 2>&1); printf '%s\n' "$out"; count "$out"

# CMake: tests/cmake_consumer uses the rbillboard_lit::rbillboard_lit INTERFACE target through
# add_subdirectory, then FetchContent (local source override), with the raylib build/raylib.mk found;
# the consumer checks RblGetCameraFrame from a C and a C++ file against raylib's GetCameraMatrix
echo "== cmake consumer (add_subdirectory, FetchContent)"
cmake_inc=$(for w in $RAYLIB_CFLAGS; do case $w in -I*) printf '%s;' "${w#-I}" ;; esac; done)
cmake_libs=$(printf '%s' "$RAYLIB_LIBS" | tr -s ' ' ';')
# The README's two CMake blocks, each as a game's whole CMakeLists.txt (as printed) beside
# tests/cmake_consumer/game_main.c, with this repository at ../rbillboard_lit and raylib as the
# package find_package(raylib 6.0) finds: a raylib-config.cmake made of what build/raylib.mk found
raylib_h=""; for w in $RAYLIB_CFLAGS; do case $w in -I*) [ -f "${w#-I}/raylib.h" ] && raylib_h=${w#-I}/raylib.h ;; esac; done
[ -z "$raylib_h" ] && [ -f /usr/include/raylib.h ] && raylib_h=/usr/include/raylib.h
raylib_v=$(sed -n 's/^#define RAYLIB_VERSION *"\([0-9.]*\).*/\1/p' "$raylib_h" 2>/dev/null | head -1)
for via in add_subdirectory FetchContent; do
  dir=$BUILD/cmake_readme_$via; rm -rf "$dir"; mkdir -p "$dir/game" "$dir/raylib-package"
  awk -v m="<!-- tested by tests/cmake_consumer ($via) -->" '$0 == m {f=1; next} f && /^```cmake$/ {p=1; next} p && /^```$/ {exit} p' README.md > "$dir/game/CMakeLists.txt"
  cp tests/cmake_consumer/game_main.c "$dir/game/main.c"
  ln -s "$PWD" "$dir/rbillboard_lit"
  { echo "add_library(raylib INTERFACE IMPORTED)"
    echo "set_target_properties(raylib PROPERTIES INTERFACE_INCLUDE_DIRECTORIES \"${cmake_inc%;}\" INTERFACE_COMPILE_DEFINITIONS SUPPORT_GPU_SKINNING=1 INTERFACE_LINK_LIBRARIES \"$cmake_libs\")"; } > "$dir/raylib-package/raylib-config.cmake"
  { echo "set(PACKAGE_VERSION \"$raylib_v\")"
    echo "if(PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION)"; echo "  set(PACKAGE_VERSION_COMPATIBLE FALSE)"
    echo "else()"; echo "  set(PACKAGE_VERSION_COMPATIBLE TRUE)"; echo "endif()"; } > "$dir/raylib-package/raylib-config-version.cmake"
  fc=""; [ $via = FetchContent ] && fc="-DFETCHCONTENT_SOURCE_DIR_RBILLBOARD_LIT=$PWD"
  if ! command -v cmake >/dev/null 2>&1; then echo "  FAIL  README cmake block ($via): cmake not installed"; fail=$((fail + 1)); continue; fi
  if [ ! -s "$dir/game/CMakeLists.txt" ]; then echo "  FAIL  README cmake block ($via): no block after its 'tested by' marker"; fail=$((fail + 1)); continue; fi
  if out=$( { cmake -S "$dir/game" -B "$dir/build" -Draylib_DIR="$(cd "$dir/raylib-package" && pwd)" $fc && cmake --build "$dir/build" -j 2 && "$dir/build/game"; } 2>&1 ) \
     && printf '%s\n' "$out" | grep -q '^cmake_consumer: .*: ok$'; then
    echo "  ok    README cmake block ($via), as printed"; printf '%s\n' "$out" | grep '^cmake_consumer:' | sed 's/^/    /'; pass=$((pass + 1))
  else
    echo "  FAIL  README cmake block ($via)"; printf '%s\n' "$out" | tail -20; fail=$((fail + 1))
  fi
done
for via in add_subdirectory FetchContent; do
  fc="-DCONSUMER_FETCHCONTENT=OFF"; [ $via = FetchContent ] && fc="-DCONSUMER_FETCHCONTENT=ON -DFETCHCONTENT_SOURCE_DIR_RBILLBOARD_LIT=$PWD"
  dir=$BUILD/cmake_consumer_$via; rm -rf "$dir"
  if ! command -v cmake >/dev/null 2>&1; then echo "  FAIL  cmake consumer ($via): cmake not installed"; fail=$((fail + 1)); continue; fi
  if out=$( { cmake -S tests/cmake_consumer -B "$dir" $fc \
                -DRAYLIB_INCLUDE_DIR="${cmake_inc%;}" -DRAYLIB_LIBRARIES="$cmake_libs" && cmake --build "$dir" -j 2 && "$dir/consumer"; } 2>&1 ) \
     && printf '%s\n' "$out" | grep -q '^cmake_consumer: .*: ok$'; then
    echo "  ok    cmake consumer ($via)"; printf '%s\n' "$out" | grep '^cmake_consumer:' | sed 's/^/    /'; pass=$((pass + 1))
  else
    echo "  FAIL  cmake consumer ($via)"; printf '%s\n' "$out" | tail -20; fail=$((fail + 1))
  fi
done

# Set-up: get-raylib.sh's one message for a missing or too old raylib, the header's own error against
# raylib 5.5, and a fresh copy's first `make run RAYLIB_SRC=<tree>` (tests/tools/setup_check.sh)
echo "== setup (missing/old raylib messages, first try in a fresh copy)"
out=$(BUILD=$BUILD RAYLIB_CFLAGS="$RAYLIB_CFLAGS" RAYLIB_LIBS="$RAYLIB_LIBS" bash tests/tools/setup_check.sh 2>&1); printf '%s\n' "$out"; count "$out"

# The examples as raylib's own: conventions, the raylib API list, raylib 6.0's examples Makefile
echo "== raylib examples (conventions, API list, raylib's examples Makefile)"
out=$(BUILD=$BUILD RAYLIB_CFLAGS="$RAYLIB_CFLAGS" RAYLIB_LIBS="$RAYLIB_LIBS" bash tests/tools/raylib_examples.sh 2>&1); printf '%s\n' "$out"; count "$out"

# The deferred example renders headlessly end to end (G-buffer, 401 lights, resolve, forward glows)
if out=$("$BUILD/deferred_headless" "$BUILD/deferred.png" "$BUILD/deferred_views.png" 2>&1) && [ -s "$BUILD/deferred.png" ]; then
  echo "  ok    deferred example renders headlessly"; printf '%s\n' "$out" | sed 's/^/    /'; pass=$((pass + 1))
else
  echo "  FAIL  deferred example renders headlessly"; printf '%s\n' "$out" | head -20; fail=$((fail + 1))
fi
# The sprite-sheet example renders headlessly (atlas from JSON, packed normal sheet, sorted soft smoke);
# the tool checks the character and the smoke are in the picture
if out=$("$BUILD/sprites_headless" "$BUILD/sprites.png" 2>&1) && [ -s "$BUILD/sprites.png" ]; then
  echo "  ok    sprite-sheet example renders headlessly"; printf '%s\n' "$out" | sed 's/^/    /'; pass=$((pass + 1))
else
  echo "  FAIL  sprite-sheet example renders headlessly"; printf '%s\n' "$out" | head -20; fail=$((fail + 1))
fi

# The lit sprite game (Kenney's CC0 sheets from examples/resources) renders headlessly; the tool checks
# both atlases read as exported, the walk cycle advances, and the robot, the moon's shadows and the
# smoke each change the picture
if out=$("$BUILD/game_headless" "$BUILD/game.png" examples 2>&1) && [ -s "$BUILD/game.png" ]; then
  echo "  ok    lit sprite game example renders headlessly"; printf '%s\n' "$out" | grep -v '^INFO' | sed 's/^/    /'; pass=$((pass + 1))
else
  echo "  FAIL  lit sprite game example renders headlessly"; printf '%s\n' "$out" | grep -v '^INFO' | head -20; fail=$((fail + 1))
fi

# The README's code as printed (tests/tools/readme_run.c): the quick start and every how-to run
# headlessly from examples/; each frame must show something lit, with no RBL warning logged
echo "== readme (the quick start and each how-to, run as printed)"
rr="$(cd "$BUILD" && pwd)/readme_run"
out=$(cd examples && ASAN_OPTIONS=detect_leaks=0 "$rr" 2>&1); printf '%s\n' "$out" | grep -E '^  (ok|FAIL)|^readme:'; count "$out"
if printf '%s\n' "$out" | grep -q "ERROR: AddressSanitizer\|runtime error:"; then echo "  FAIL  readme: sanitizer report"; printf '%s\n' "$out" | grep -A5 "ERROR: AddressSanitizer\|runtime error:" | head -20; fail=$((fail + 1)); fi

# Static check of every spliced stage in every dialect (330, 300 es, 120, 100). glslangValidator
# checks syntax and types per #version; it does not enforce GLSL ES 1.00's Appendix A indexing limits,
# which the strict ES 2.0 run below exercises on Mesa.
echo "== glsl (glslangValidator, every dialect)"
rm -rf "$BUILD/glsl"
if ! command -v glslangValidator >/dev/null 2>&1; then echo "  FAIL  glslangValidator not installed (tests/tools/deps.sh installs glslang-tools)"; fail=$((fail + 1))
elif out=$("$BUILD/tests/splice_shaders" "$BUILD/glsl" 2>&1); then
  echo "    $out"
  gp=0; gf=0
  for f in "$BUILD"/glsl/*/*; do
    if v=$(glslangValidator "$f" 2>&1); then gp=$((gp + 1)); else gf=$((gf + 1)); echo "  FAIL  $f"; printf '%s\n' "$v" | head -5; fi
  done
  echo "glsl: $gp passed, $gf failed"; count "glsl: $gp passed, $gf failed"
else echo "  FAIL  splice_shaders: $out"; fail=$((fail + 1)); fi

for suite in test_cpu test_cpu_san; do
  echo "== $suite"
  out=$("$BUILD/tests/$suite" 2>&1); printf '%s\n' "$out"; count "$out"
done
echo "== test_api_san (egl, ASan+UBSan+LSan)"
out=$(RBL_TEST_CONTEXT=egl ASAN_OPTIONS=detect_leaks=1 "$BUILD/tests/test_api_san" 2>&1); printf '%s\n' "$out"; count "$out"
if printf '%s\n' "$out" | grep -q "ERROR: \(Address\|Leak\)Sanitizer"; then echo "  FAIL  test_api_san: sanitizer report"; fail=$((fail + 1)); fi
echo "== test_contracts (egl, ASan+UBSan, one process per case)"
out=$(RBL_TEST_CONTEXT=egl ASAN_OPTIONS=exitcode=66:detect_leaks=0 "$BUILD/tests/test_contracts" rbillboard_lit.h 2>&1); printf '%s\n' "$out"; count "$out"
echo "== test_alloc (egl, ASan+UBSan, the header's allocator failing at every call)"
out=$(RBL_TEST_CONTEXT=egl ASAN_OPTIONS=detect_leaks=0 "$BUILD/tests/test_alloc" 2>&1); printf '%s\n' "$out"; count "$out"
# Teardown in every order (unloads, RblClose, CloseWindow; C++ RAII) with a real raylib window on
# a virtual X display
for suite in test_teardown test_teardown_cpp; do
  echo "== $suite (xvfb, ASan+UBSan)"
  out=$(ASAN_OPTIONS=detect_leaks=0 xvfb-run -a "$BUILD/tests/$suite" 2>&1 | grep -v "^Can't open /dev/input"); printf '%s\n' "$out"; count "$out"
done
# Atlas readers under libFuzzer + ASan + UBSan: FUZZ_SECONDS (default 8) per format from the
# hand-written seeds; new inputs go to a scratch corpus under $BUILD, never into the repository
echo "== fuzz (libFuzzer, ASan+UBSan, ${FUZZ_SECONDS:-8} s per format)"
fp=0; ff=0
for f in texturepacker aseprite libgdx; do
  dict=tests/fuzz/json.dict; [ $f = libgdx ] && dict=tests/fuzz/libgdx.dict
  rm -rf "$BUILD/fuzz/work-$f"; mkdir -p "$BUILD/fuzz/work-$f"
  root=$(pwd)
  if out=$(cd "$BUILD/fuzz" && "./fuzz_$f" -max_total_time="${FUZZ_SECONDS:-8}" -dict="$root/$dict" -print_final_stats=1 "work-$f" "$root/tests/fuzz/corpus/$f" 2>&1); then
    echo "  ok    fuzz_$f: $(printf '%s\n' "$out" | grep -E '^Done [0-9]+ runs' | tail -1)"; fp=$((fp + 1))
  else
    echo "  FAIL  fuzz_$f (crash input kept in $BUILD/fuzz)"; printf '%s\n' "$out" | grep -E 'ERROR|invariant|SUMMARY|crash-|Test unit' | head -10; ff=$((ff + 1))
  fi
done
echo "fuzz: $fp passed, $ff failed"; count "fuzz: $fp passed, $ff failed"
for ctx in egl osmesa; do
  echo "== test_gpu ($ctx, ASan+UBSan)"
  out=$(RBL_TEST_CONTEXT=$ctx ASAN_OPTIONS=detect_leaks=0 "$BUILD/tests/test_gpu" 2>&1); printf '%s\n' "$out"; count "$out"
  if printf '%s\n' "$out" | grep -q "ERROR: AddressSanitizer\|runtime error:"; then echo "  FAIL  test_gpu ($ctx): sanitizer report"; fail=$((fail + 1)); fi
done
# The same suite on raylib built for each other graphics API, on a strict context of that version
# (Mesa's overrides): ES 3.0 / GLSL ES 3.00 runs everything; ES 2.0 and GL 2.1 the forward path,
# with instanced and deferred refused (their GLSL 3 tests listed as n/a, the refusals tested)
for ctx in gles3 gles2 gl21; do
  echo "== test_gpu ($ctx)"
  case $ctx in
    gles3) env="MESA_GLES_VERSION_OVERRIDE=3.0" ;;
    gles2) env="MESA_GLES_VERSION_OVERRIDE=2.0" ;;
    gl21) env="MESA_GL_VERSION_OVERRIDE=2.1 MESA_GLSL_VERSION_OVERRIDE=120" ;;
  esac
  out=$(env $env RBL_TEST_CONTEXT=$ctx ASAN_OPTIONS=detect_leaks=0 "$BUILD/tests/test_gpu_$ctx" 2>&1); printf '%s\n' "$out"; count "$out"
  if printf '%s\n' "$out" | grep -q "ERROR: AddressSanitizer\|runtime error:"; then echo "  FAIL  test_gpu ($ctx): sanitizer report"; fail=$((fail + 1)); fi
done

# The browser: the GPU subset built with emscripten, in headless Chromium (WebGL2 on SwiftShader)
echo "== test_web (headless Chromium over 127.0.0.1, WebGL2 on SwiftShader; tests/web/)"
out=$(python3 tests/web/run.py test "$BUILD/web/test" 2>&1); printf '%s\n' "$out"; count "$out"

# The showcase page as a web developer would take it (tests/web/page_check.html): sizes and
# devicePixelRatio, opaque and not blank, input, context loss and restore, the WebGL1 build, no WebGL;
# then the README's minimal shell as printed. Pictures in $BUILD/web/shots/
echo "== showcase page (headless Chromium: fills and follows, opaque, input, context loss, no WebGL; README shell)"
for m in main "dpr --force-device-scale-factor=2" "gl1 --disable-webgl2" "nowebgl --disable-webgl" shell "shellnowebgl --disable-webgl"; do
  out=$(python3 tests/web/run.py page "$BUILD/web" $m 2>&1); printf '%s\n' "$out"; count "$out"
done

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
