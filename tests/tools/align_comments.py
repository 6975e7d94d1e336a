#!/usr/bin/env python3
"""Aligns the trailing // comments of the header's public declarations (RBLAPI lines) and of the
members of its structs and enums: the declarations of one group (a run of consecutive commented
lines) at the column after its longest code, struct and enum members at column 36 (raylib's) or
after the struct's longest member; code reaching column LIMIT keeps one space.
   usage: align_comments.py check|fix   (check fails when a fix would change the header)"""
import re, sys, os
os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
HDR = 'rbillboard_lit.h'
LIMIT = 100
lines = open(HDR).read().split('\n')
impl = next(i for i, l in enumerate(lines) if l.startswith('#if defined(RBILLBOARD_LIT_IMPLEMENTATION)'))
shaders = next(i for i, l in enumerate(lines) if '>>shaders' in l)

def split(l):
    """(code, comment) when l is code with a trailing // comment outside a string, else None"""
    if l.lstrip().startswith('//') or l.lstrip().startswith('*') or '"' in l.split('//')[0]: return None
    m = re.match(r'^(.*?\S)\s+(//.*)$', l)
    if not m or '//' in m.group(1): return None
    return m.group(1), m.group(2)

def candidate(i, l, inside):
    return (l.startswith('RBLAPI ') or inside) and split(l) is not None

out = list(lines)
inside = False
runs, run = [], []
block = 0                                   # struct/enum number of each run (0 = declarations)
blocks = []
for i, l in enumerate(lines):
    if i >= shaders and i < impl: continue      # generated shader strings
    if re.match(r'^\s*typedef (struct|enum|union)\b.*\{\s*$', l) or re.match(r'^\s*(typedef )?(struct|enum) \w* ?\{\s*$', l) or re.match(r'^\s*enum \{\s*$', l):
        inside = True; block = i
    if inside and re.match(r'^\s*\}', l): inside = False
    if candidate(i, l, inside and not l.strip().startswith('}')):
        if run and blocks and blocks[-1] != (block if inside else 0): runs.append(run); run = []
        if not run: blocks.append(block if inside else 0)
        run.append(i); continue
    if run and not inside: runs.append(run); run = []
if run: runs.append(run)
width = {}                                  # widest fitting member per struct
for run, b in zip(runs, blocks):
    if b: width[b] = max([width.get(b, 35)] + [len(split(lines[i])[0]) for i in run if len(split(lines[i])[0]) + 1 < LIMIT])
for run, b in zip(runs, blocks):
    codes = [split(lines[i])[0] for i in run]
    fit = [len(c) for c in codes if len(c) + 1 < LIMIT]
    col = (width[b] + 1) if b else ((max(fit) + 1) if fit else None)
    for i, c in zip(run, codes):
        com = split(lines[i])[1]
        out[i] = (c + ' '*(col - len(c)) + com) if (col is not None and len(c) < col) else (c + ' ' + com)
changed = sum(1 for a, b in zip(lines, out) if a != b)
if sys.argv[1:] == ['fix']:
    open(HDR, 'w').write('\n'.join(out)); print('align_comments: %d lines realigned' % changed)
else:
    print(('  ok    ' if changed == 0 else '  FAIL  ') + 'trailing comments of declarations aligned (%d lines off; tests/tools/align_comments.py fix)' % changed)
    print('align: %d passed, %d failed' % (changed == 0, changed != 0))
    sys.exit(1 if changed else 0)
