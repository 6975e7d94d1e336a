#!/usr/bin/env bash
# Receiver cost of several header versions, measured alternately in one session:
#   tests/bench/receiver_ab.sh [rounds] [label=commit|worktree ...]
# Each label's rbillboard_lit.h (a commit's, or the working tree's for "worktree") is built with
# tests/bench/receiver_ab.c (AB_OMNI where the header has omni maps); the binaries then run
# A B C A B C ... `rounds` times; every run prints its per-variant ratios to the unshadowed draw.
set -eu
rounds=${1:-3}; shift || true
[ $# -gt 0 ] || set -- pre=fcc39be main=main branch=worktree
BUILD=${BUILD:-build}
out="$BUILD/receiver_ab"
mkdir -p "$out"
RAYLIB_CFLAGS=$(sed -n 's/^RAYLIB_CFLAGS=//p' "$BUILD/raylib.mk")
RAYLIB_LIBS=$(sed -n 's/^RAYLIB_LIBS=//p' "$BUILD/raylib.mk")
labels=()
for spec in "$@"; do
  label=${spec%%=*}; rev=${spec#*=}
  mkdir -p "$out/$label"
  if [ -n "${AB_NOBUILD:-}" ]; then :; elif [ "$rev" = worktree ]; then cp rbillboard_lit.h "$out/$label/"; else git show "$rev:rbillboard_lit.h" > "$out/$label/rbillboard_lit.h"; fi
  omni=""; grep -q "RblFitShadowCascades" "$out/$label/rbillboard_lit.h" && omni="-DAB_OMNI"
  grep -q "RblShading shading" "$out/$label/rbillboard_lit.h" && omni="$omni -DAB_SHADING"
  [ -n "${AB_NOBUILD:-}" ] && [ -x "$out/$label/receiver_ab" ] || cc -std=c99 -D_DEFAULT_SOURCE -O2 -DRBL_INSTRUMENTS $omni -I"$out/$label" -Itests -Itests/bench $RAYLIB_CFLAGS \
     tests/bench/receiver_ab.c tests/harness.c -o "$out/$label/receiver_ab" $RAYLIB_LIBS
  labels+=("$label")
done
for r in $(seq 1 "$rounds"); do
  for label in "${labels[@]}"; do RBL_TEST_CONTEXT=${RBL_TEST_CONTEXT:-egl} "$out/$label/receiver_ab" "$label" | tail -n 1; done
done
