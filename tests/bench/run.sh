#!/usr/bin/env bash
# Runs the benchmarks (built by `make bench`) into a fresh $BUILD/bench/results.csv
# (suite,case,metric,value,unit) and prints the rows as an aligned table.
set -eu
BUILD=${BUILD:-build}
csv="$BUILD/bench/results.csv"
mkdir -p "$BUILD/bench"
rm -f "$csv"
echo "suite,case,metric,value,unit" > "$csv"

echo "== bench_geometry"
BENCH_CSV="$csv" "$BUILD/bench/bench_geometry"

echo
echo "== bench_materials"
BENCH_CSV="$csv" "$BUILD/bench/bench_materials"

echo
echo "== bench_lighting"
BENCH_CSV="$csv" "$BUILD/bench/bench_lighting"

echo
echo "== bench_deferred"
BENCH_CSV="$csv" "$BUILD/bench/bench_deferred"

echo
echo "== bench_clustered"
BENCH_CSV="$csv" "$BUILD/bench/bench_clustered"

echo
echo "== bench_shadows"
BENCH_CSV="$csv" "$BUILD/bench/bench_shadows"

echo
echo "== bench_thin"
BENCH_CSV="$csv" "$BUILD/bench/bench_thin"

echo
echo "== bench_deferred_thin"
BENCH_CSV="$csv" "$BUILD/bench/bench_deferred_thin"

echo
echo "== bench_overdraw"
BENCH_CSV="$csv" "$BUILD/bench/bench_overdraw"

echo
echo "== bench_skinning"
BENCH_CSV="$csv" "$BUILD/bench/bench_skinning"

echo
echo "== bench_sprites"
RBL_TEST_CONTEXT=egl BENCH_CSV="$csv" "$BUILD/bench/bench_sprites"

echo
echo "== bench_polygon"
RBL_TEST_CONTEXT=egl BENCH_CSV="$csv" "$BUILD/bench/bench_polygon"

echo
echo "== bench_platforms (GL 3.3 core, strict ES 3.0, ES 2.0, GL 2.1)"
# Cold compilations (what a page or a first run pays): Mesa's on-disk shader cache off
export MESA_SHADER_CACHE_DISABLE=true
RBL_TEST_CONTEXT=egl BENCH_CSV="$csv" "$BUILD/bench/bench_platforms_egl"
MESA_GLES_VERSION_OVERRIDE=3.0 RBL_TEST_CONTEXT=gles3 BENCH_CSV="$csv" "$BUILD/bench/bench_platforms_gles3"
MESA_GLES_VERSION_OVERRIDE=2.0 RBL_TEST_CONTEXT=gles2 BENCH_CSV="$csv" "$BUILD/bench/bench_platforms_gles2"
MESA_GL_VERSION_OVERRIDE=2.1 MESA_GLSL_VERSION_OVERRIDE=120 RBL_TEST_CONTEXT=gl21 BENCH_CSV="$csv" "$BUILD/bench/bench_platforms_gl21"
# Same machine, same run: the showcase frame time of ES 3 (and the others) over GL 3.3's
awk -F, '$1 == "platforms" && $3 == "ms_per_frame" { split($2, a, "_"); ms[a[1]] = $4 }
         END { for (c in ms) if (c != "egl" && ms["egl"] > 0) printf "platforms,showcase_%s_over_gl33,frame_time_ratio,%.3f,x\n", c, ms[c]/ms["egl"] }' "$csv" > "$csv.ratio"
cat "$csv.ratio" | sed 's/^/  /'
cat "$csv.ratio" >> "$csv"; rm -f "$csv.ratio"
unset MESA_SHADER_CACHE_DISABLE

echo
echo "== bench_blend (suite sprites: sorting cost, alpha coverage per mip)"
RBL_TEST_CONTEXT=egl BENCH_CSV="$csv" "$BUILD/bench/bench_blend"

echo
echo "== bench_api"
BENCH_CSV="$csv" "$BUILD/bench/bench_api"

echo
echo "== $csv"
if command -v column >/dev/null 2>&1; then
  column -t -s, "$csv"
else
  awk -F, '{ printf "%-10s %-28s %-26s %14s %s\n", $1, $2, $3, $4, $5 }' "$csv"
fi
