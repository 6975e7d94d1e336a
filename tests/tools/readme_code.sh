#!/usr/bin/env bash
# The README's runnable code, as printed, for tests/tools/readme_run.c: each ```c block preceded by a
# line `<!-- run: NAME -->`. The block named quickstart is a whole program (its main renamed); every
# other is the body of a function given `Model model` and `Camera3D camera`, as the language matrix
# compiles it. Also checks the guide (the README above "## API index"): every c block there is
# marked, each marked how-to shows its own picture (examples/resources/howto_NAME.png) above it.
#   usage: readme_code.sh README.md OUT.inc
# The guide's size is held too: at most 4,000 words (code included), and at most 400 before the
# quick start's program.
set -eu
readme=$1; out=$2
awk '
  /^<!-- run: [a-z0-9_]+ -->$/ { name = $3; next }
  /^## API index/ { guide = 0 }
  NR == 1 { guide = 1 }
  /^```c$/ {
    if (name == "") { if (guide) { print "readme_code: a c block in the guide without a run marker (line " NR ")" > "/dev/stderr"; bad = 1 } skip = 1; next }
    inblock = 1; names[++n] = name
    if (name == "quickstart") print "#define main readme_quickstart"
    else print "static void howto_" name "(Model model, Camera3D camera)\n{\n(void)model; (void)camera;"
    print "#line " NR + 1 " \"README.md\""
    next
  }
  /^```$/ && inblock { if (name == "quickstart") print "#undef main"; else print "}"; inblock = 0; name = ""; next }
  /^```$/ && skip { skip = 0; next }
  inblock { print; next }
  { if (name != "" && !/^$/ && !/^!\[/ ) { } }
  END {
    print "static const ReadmeProgram readmePrograms[] = {"
    for (i = 1; i <= n; i++) if (names[i] != "quickstart") print "    { \"" names[i] "\", howto_" names[i] " },"
    print "};"
    if (bad) exit 1
  }' "$readme" > "$out"
grep -q '^#define main readme_quickstart' "$out" || { echo "readme_code: no block marked <!-- run: quickstart -->" >&2; exit 1; }
# each how-to shows its own picture somewhere above its block
for name in $(sed -n 's/^<!-- run: \([a-z0-9_]*\) -->$/\1/p' "$readme" | grep -v '^quickstart$'); do
  grep -q "examples/resources/howto_$name.png" "$readme" || { echo "readme_code: how-to $name shows no picture (examples/resources/howto_$name.png)" >&2; exit 1; }
done
guide=$(awk '/^## API index/ {exit} {print}' "$readme" | wc -w)
before=$(awk '/^<!-- run: quickstart -->$/ {exit} {print}' "$readme" | wc -w)
[ "$guide" -le 4000 ] || { echo "readme_code: the guide (above ## API index) has $guide words, more than 4000" >&2; exit 1; }
[ "$before" -le 400 ] || { echo "readme_code: $before words before the quick start, more than 400" >&2; exit 1; }
echo "readme_code: guide $guide words, $before before the quick start; $(grep -c '^<!-- run: ' "$readme") programs"
