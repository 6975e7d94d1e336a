#!/usr/bin/env python3
"""Keeps each GPU test registered beside its body: every tests/test_*.c that gpu_tests.h includes
ends with `#define RBL_<FILE>_TESTS` listing its tests, and gpu_tests.h's rblGpuTests is the list of
those macros. `fix` moves registrations found in gpu_tests.h into their files' macros (run it after
merging a branch that registered tests there); `check` fails when a test function is registered
nowhere, twice, or in another file's list.
   usage: test_lists.py check|fix"""
import re, sys, os
os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
HDR = 'tests/gpu_tests.h'
hdr = open(HDR).read()
files = re.findall(r'#include "(test_[a-z0-9_]+\.c)"', hdr)
defined = {}      # test name -> file
for f in files:
    for m in re.finditer(r'^static void (test_[a-z0-9_]+)\(void\)', open('tests/' + f).read(), re.M):
        defined[m.group(1)] = f
def macro(f): return 'RBL_' + f[len('test_'):-2].upper() + '_TESTS'
def file_list(f):
    src = open('tests/' + f).read()
    m = re.search(r'^#define ' + macro(f) + r' \\\n((?:.*\\\n)*.*\n)', src, re.M)
    return (re.findall(r'RT_TEST(?:_GLSL3)?\((test_[a-z0-9_]+)\)', m.group(1)) if m else None), src, m
start = hdr.index('static const RtTest rblGpuTests[] = {')
end = hdr.index('};', start)
body = hdr[start:end]
loose = re.findall(r'(RT_TEST(?:_GLSL3)?)\((test_[a-z0-9_]+)\)', body)
mode = sys.argv[1] if len(sys.argv) > 1 else 'check'
if mode == 'fix':
    for f in files:
        names, src, m = file_list(f)
        entries = [] if names is None else re.findall(r'RT_TEST(?:_GLSL3)?\(test_[a-z0-9_]+\)', m.group(1))
        entries += ['%s(%s)' % (kind, name) for kind, name in loose if defined.get(name) == f]
        if not entries: continue
        block = '#define %s \\\n' % macro(f) + ', \\\n'.join('    ' + e for e in entries) + '\n'
        src = (src[:m.start()] + block + src[m.end():]) if m else (src.rstrip('\n') + '\n\n// The tests of this file, in order (gpu_tests.h lists every file\'s)\n' + block)
        open('tests/' + f, 'w').write(src)
    lists = [macro(f) for f in files if file_list(f)[0]]
    hdr = hdr[:start] + 'static const RtTest rblGpuTests[] = {\n' + ''.join('        %s,\n' % l for l in lists) + '    ' + hdr[end:]
    open(HDR, 'w').write(hdr)
    loose = []
# check
bad = []
registered = {}
for f in files:
    names = file_list(f)[0] or []
    for n in names:
        if n in registered: bad.append('%s registered twice' % n)
        registered[n] = f
        if defined.get(n) != f: bad.append('%s listed in %s, defined in %s' % (n, f, defined.get(n)))
    if names and macro(f) not in body and mode == 'check': bad.append('%s not in rblGpuTests' % macro(f))
for kind, n in loose: bad.append('%s registered in gpu_tests.h, not in its file' % n)
for n, f in defined.items():
    if n not in registered and n not in [x for _, x in loose]: bad.append('%s (%s) registered nowhere' % (n, f))
for b in bad: print('  FAIL  ' + b)
print('  %s  GPU tests registered beside their bodies: %d tests in %d files' % ('ok  ' if not bad else 'FAIL', len(registered), len([f for f in files if file_list(f)[0]])))
print('test-lists: %d passed, %d failed' % (0 if bad else 1, 1 if bad else 0))
sys.exit(1 if bad else 0)
