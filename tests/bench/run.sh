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
echo "== bench_shadows"
BENCH_CSV="$csv" "$BUILD/bench/bench_shadows"

echo
echo "== bench_skinning"
BENCH_CSV="$csv" "$BUILD/bench/bench_skinning"

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
