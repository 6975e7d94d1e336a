#!/usr/bin/env bash
# make test-quick: the edit loop's subset of tests/run.sh (CPU suite, contracts, GPU suite on EGL, the
# README's API index and programs). Ends with "N passed, N failed" as make test does; make test runs
# everything else (other contexts, sanitizer builds, the language matrix, fuzzing, the browser).
set -u
BUILD=${BUILD:-build}
pass=0; fail=0
count() {
  local line; line=$(printf '%s\n' "$1" | grep -E '^[a-z][a-z0-9_-]*: [0-9]+ passed, [0-9]+ failed$' | tail -1)
  if [ -z "$line" ]; then echo "  FAIL  suite did not finish (no summary line)"; fail=$((fail + 1)); return; fi
  local p f; p=$(echo "$line" | sed -E 's/.*: ([0-9]+) passed.*/\1/'); f=$(echo "$line" | sed -E 's/.* ([0-9]+) failed$/\1/')
  pass=$((pass + p)); fail=$((fail + f))
}
show() { printf '%s\n' "$1" | grep -E '^  FAIL|^[a-z][a-z0-9_-]*: [0-9]+ passed' ; }
echo "== test-lists (each GPU test registered beside its body)"
out=$(python3 tests/tools/test_lists.py check 2>&1); printf '%s\n' "$out"; count "$out"
out=$(python3 tests/tools/align_comments.py check 2>&1); show "$out"; count "$out"
echo "== api (README index, CONFIGURATION)"
out=$(bash tests/tools/api_index.sh check rbillboard_lit.h README.md 2>&1); show "$out"; count "$out"
echo "== test_cpu"
out=$("$BUILD/tests/test_cpu" 2>&1); show "$out"; count "$out"
echo "== test_contracts (egl)"
out=$(RBL_TEST_CONTEXT=egl ASAN_OPTIONS=exitcode=66:detect_leaks=0 "$BUILD/tests/test_contracts" rbillboard_lit.h 2>&1); show "$out"; count "$out"
echo "== test_gpu (egl)"
out=$(RBL_TEST_CONTEXT=egl ASAN_OPTIONS=detect_leaks=0 "$BUILD/tests/test_gpu" 2>&1); show "$out"; count "$out"
echo "== readme"
rr="$(cd "$BUILD" && pwd)/readme_run"
out=$(cd examples && ASAN_OPTIONS=detect_leaks=0 "$rr" 2>&1); show "$out"; count "$out"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
