#!/usr/bin/env python3
"""Headless Chromium over loopback for the browser builds.

  run.py test DIR [FILTER]           serves DIR on 127.0.0.1, opens DIR/index.html (the test page),
                                     prints every line the page posts to /log, ends on '@done'
                                     (or the time limit) and makes sure the last line is the suite's
                                     'web: N passed, N failed'; exit 0 only when it says 0 failed
  run.py shot DIR OUT.png W H [MS]   serves DIR and screenshots DIR/index.html after MS of page time

Chromium runs headless with SwiftShader (software WebGL2), its own throw-away profile, no network
beyond the loopback server.
"""
import http.server, os, re, shutil, socketserver, subprocess, sys, tempfile, threading, time, urllib.parse

CHROMIUM_FLAGS = ['--headless', '--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
                  '--ignore-gpu-blocklist', '--disable-dev-shm-usage', '--no-first-run', '--no-default-browser-check',
                  '--disable-background-networking', '--disable-extensions', '--mute-audio',
                  '--enable-logging=stderr', '--v=0']    # the page's console lands in chromium.log
# WEB_CHROMIUM_FLAGS adds flags, e.g. --disable-webgl2 to see the page's WebGL1 fallback
CHROMIUM_FLAGS += os.environ.get('WEB_CHROMIUM_FLAGS', '').split()
TIME_LIMIT = float(os.environ.get('WEB_TEST_TIMEOUT', '900'))
SUMMARY = re.compile(r'^web: (\d+) passed, (\d+) failed$')


def chromium():
    for name in ('chromium', 'chromium-browser', 'google-chrome'):
        path = shutil.which(name)
        if path:
            return path
    sys.exit('run.py: no chromium (tests/tools/deps.sh web installs it)')


def serve(directory, on_line):
    class Handler(http.server.SimpleHTTPRequestHandler):
        def __init__(self, *a, **k):
            super().__init__(*a, directory=directory, **k)

        def log_message(self, *a):
            pass

        def end_headers(self):
            self.send_header('Cache-Control', 'no-store')
            super().end_headers()

        def do_POST(self):
            n = int(self.headers.get('Content-Length', '0'))
            line = self.rfile.read(n).decode('utf-8', 'replace')
            self.send_response(204)
            self.end_headers()
            if self.path == '/log':
                on_line(line)

    Handler.extensions_map = dict(http.server.SimpleHTTPRequestHandler.extensions_map, **{'.wasm': 'application/wasm', '.js': 'text/javascript'})
    server = socketserver.ThreadingTCPServer(('127.0.0.1', 0), Handler)
    server.daemon_threads = True
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def run_test(directory, filt):
    lines, done = [], threading.Event()

    def on_line(line):
        if line == '@done':
            done.set()
            return
        lines.append(line)
        if not SUMMARY.match(line):     # printed once, last, by run_test
            print(line, flush=True)

    server = serve(directory, on_line)
    port = server.server_address[1]
    url = 'http://127.0.0.1:%d/index.html' % port + ('?filter=' + urllib.parse.quote(filt) if filt else '')
    profile = tempfile.mkdtemp(prefix='rbl-web-')
    log = open(os.path.join(directory, 'chromium.log'), 'w')
    start = time.time()
    proc = subprocess.Popen([chromium()] + CHROMIUM_FLAGS + ['--user-data-dir=' + profile, '--remote-debugging-port=0', url],
                            stdout=log, stderr=subprocess.STDOUT)
    finished = done.wait(TIME_LIMIT)
    proc.terminate()
    try:
        proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()
    server.shutdown()
    shutil.rmtree(profile, ignore_errors=True)
    elapsed = time.time() - start
    summary = [SUMMARY.match(l) for l in lines if SUMMARY.match(l)]
    if not finished:
        print('  FAIL  the page did not finish within %.0f s (see %s/chromium.log)' % (TIME_LIMIT, directory))
    if not summary:
        # The suite died before its closing line: count that as one failure, keep what passed
        passed = sum(1 for l in lines if l.startswith('  ok    '))
        failed = sum(1 for l in lines if l.startswith('  FAIL  ')) + 1
        print('  FAIL  suite did not finish (no summary line)')
        print('web: %d passed, %d failed' % (passed, failed))
        return 1
    print('  (browser run %.1f s)' % elapsed)
    print(summary[-1].group(0))
    return 0 if (finished and summary[-1].group(2) == '0') else 1


def run_shot(directory, out, width, height, ms):
    server = serve(directory, lambda line: print(line, flush=True))
    port = server.server_address[1]
    profile = tempfile.mkdtemp(prefix='rbl-web-')
    cmd = [chromium()] + CHROMIUM_FLAGS + ['--user-data-dir=' + profile, '--hide-scrollbars',
                                           '--window-size=%d,%d' % (width, height), '--virtual-time-budget=%d' % ms,
                                           '--screenshot=' + os.path.abspath(out), 'http://127.0.0.1:%d/index.html' % port]
    with open(os.path.join(directory, 'chromium-shot.log'), 'w') as log:
        rc = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, timeout=300).returncode
    server.shutdown()
    shutil.rmtree(profile, ignore_errors=True)
    if rc != 0 or not os.path.exists(out):
        print('run.py: screenshot failed (chromium exit %d)' % rc)
        return 1
    print('run.py: wrote %s (%dx%d)' % (out, width, height))
    return 0


if __name__ == '__main__':
    if len(sys.argv) >= 3 and sys.argv[1] == 'test':
        sys.exit(run_test(sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else ''))
    if len(sys.argv) >= 6 and sys.argv[1] == 'shot':
        sys.exit(run_shot(sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5]), int(sys.argv[6]) if len(sys.argv) > 6 else 5000))
    sys.exit(__doc__)
