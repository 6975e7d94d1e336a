#!/usr/bin/env bash
# Splices shaders/*.glsl into rbillboard_lit.h between the RBL-SHADERS-BEGIN/END markers as arrays of
# line strings named rbl__shader_<file> (dots -> underscores, .glsl dropped; NULL-terminated, because
# ISO C99 only promises 4095-character string literals), plus a table of them that the tests use to
# prove the embedded copy equals shaders/. Usage: shaders/embed.sh [header] [outfile]
set -eu
header=${1:-rbillboard_lit.h}
out=${2:-$header}
dir=$(dirname "$0")
tmp=$(mktemp)
{
  names=""
  for f in "$dir"/*.glsl; do
    base=$(basename "$f" .glsl); name=rbl__shader_$(echo "$base" | tr '.-' '__')
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
} > "$tmp"
awk -v gen="$tmp" '
  /^\/\/ RBL-SHADERS-BEGIN/ { print; while ((getline line < gen) > 0) print line; skip=1; next }
  /^\/\/ RBL-SHADERS-END/ { skip=0 }
  !skip { print }' "$header" > "$tmp.h"
rm -f "$tmp"
if [ "$out" = "$header" ] && cmp -s "$tmp.h" "$header"; then rm -f "$tmp.h"; exit 0; fi
mv "$tmp.h" "$out"
