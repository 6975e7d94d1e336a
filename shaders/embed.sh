#!/usr/bin/env bash
# Splices shaders/*.glsl into rbillboard_lit.h between the RBL-SHADERS-BEGIN/END markers:
#   - each file as an array of line strings named rbl__shader_<file> (dots -> underscores, .glsl
#     dropped; NULL-terminated, because ISO C99 only promises 4095-character string literals), equal
#     to the file byte for byte (the tests compare them with shaders/);
#   - each stage file (*.vs.glsl, *.fs.glsl) as rbl__pass_<file>: its parts in include order. A file
#     names what it needs with lines `#include "name.glsl"`; the parts are the depth-first closure,
#     each file once, dependencies first. The loader skips the #include lines when it joins them.
# Usage: shaders/embed.sh [header] [outfile]
set -eu
header=${1:-rbillboard_lit.h}
out=${2:-$header}
dir=$(dirname "$0")
tmp=$(mktemp)
symbol() { echo "rbl__shader_$(basename "$1" .glsl | tr '.-' '__')"; }
order=""
visit() {   # appends $1 (a file name) and, first, what it includes to $order
  case " $order " in *" $1 "*) return ;; esac
  [ -f "$dir/$1" ] || { echo "embed.sh: $1 is included but missing from shaders/" >&2; exit 1; }
  local inc
  for inc in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$dir/$1"); do visit "$inc"; done
  order="$order $1"
}
{
  names=""
  for f in "$dir"/*.glsl; do
    base=$(basename "$f" .glsl); name=$(symbol "$f")
    names="$names $base:$name"
    echo "static const char *const $name[] = {"
    # Escape \ and ", keep every line (a trailing \n per line), so the string equals the file byte for byte.
    sed -e 's/\\/\\\\/g' -e 's/"/\\"/g' -e 's/^/    "/' -e 's/$/\\n",/' "$f"
    echo "    NULL };"
  done
  echo "// Every embedded shader by file name (tests compare these with shaders/*.glsl)"
  echo "static const struct { const char *file; const char *const *source; } rbl__shaderFiles[] = {"
  for n in $names; do echo "    { \"${n%%:*}.glsl\", ${n#*:} },"; done
  echo "};"
  echo "// Each stage with its includes resolved, dependencies first (the loader joins these)"
  passes=""
  for f in "$dir"/*.vs.glsl "$dir"/*.fs.glsl; do
    order=""
    visit "$(basename "$f")"
    pass=rbl__pass_$(basename "$f" .glsl | tr '.-' '__')
    passes="$passes $(basename "$f"):$pass"
    printf 'static const char *const *const %s[] = {' "$pass"
    for part in $order; do printf ' %s,' "$(symbol "$part")"; done
    echo ' NULL };'
  done
  echo "static const struct { const char *file; const char *const *const *parts; } rbl__passFiles[] = {"
  for p in $passes; do echo "    { \"${p%%:*}\", ${p#*:} },"; done
  echo "};"
} > "$tmp"
awk -v gen="$tmp" '
  /^\/\/ RBL-SHADERS-BEGIN/ { print; while ((getline line < gen) > 0) print line; skip=1; next }
  /^\/\/ RBL-SHADERS-END/ { skip=0 }
  !skip { print }' "$header" > "$tmp.h"
rm -f "$tmp"
if [ "$out" = "$header" ] && cmp -s "$tmp.h" "$header"; then rm -f "$tmp.h"; exit 0; fi
mv "$tmp.h" "$out"
