#!/usr/bin/env python3
"""Headless Chromium over loopback for the browser builds.

  run.py test DIR [FILTER]           serves DIR on 127.0.0.1, opens DIR/index.html (the test page),
                                     prints every line the page posts to /log, ends on '@done'
                                     (or the time limit) and makes sure the last line is the suite's
                                     'web: N passed, N failed'; exit 0 only when it says 0 failed
  run.py shot DIR OUT.png W H [MS]   serves DIR and screenshots DIR/index.html after MS of page time
  run.py page DIR MODE [FLAG...]     serves DIR, opens DIR/page_check.html?mode=MODE (the showcase
                                     page's checks) with the extra Chromium flags, prints its lines,
                                     writes the canvas pictures it posts to DIR/shots/<name>.png; the
                                     last line is 'page_MODE: N passed, N failed'; exit 0 only for 0 failed

Chromium runs headless with SwiftShader (software WebGL2), its own throw-away profile, no network
beyond the loopback server.
"""
import base64, http.server, os, re, shutil, socketserver, subprocess, sys, tempfile, threading, time, urllib.parse

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


def serve(directory, on_line, on_shot=None):
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
            elif self.path.startswith('/shot?name=') and on_shot:
                on_shot(urllib.parse.unquote(self.path[len('/shot?name='):]), line)

    Handler.extensions_map = dict(http.server.SimpleHTTPRequestHandler.extensions_map, **{'.wasm': 'application/wasm', '.js': 'text/javascript'})
    server = socketserver.ThreadingTCPServer(('127.0.0.1', 0), Handler)
    server.daemon_threads = True
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def run_test(directory, filt, page='index.html', query='', summary_re=SUMMARY, flags=(), name='web', time_limit=TIME_LIMIT):
    lines, done = [], threading.Event()

    def on_line(line):
        if line == '@done':
            done.set()
            return
        lines.append(line)
        if not summary_re.match(line):     # printed once, last, by run_test
            print(line, flush=True)

    def on_shot(shot, data_url):        # a canvas picture the page posted: data:image/png;base64,...
        os.makedirs(os.path.join(directory, 'shots'), exist_ok=True)
        with open(os.path.join(directory, 'shots', os.path.basename(shot) + '.png'), 'wb') as f:
            f.write(base64.b64decode(data_url.split(',', 1)[1]))

    missing = [f for f in (page,) if not os.path.exists(os.path.join(directory, f))]
    if missing:     # a page that is not there would only time out
        print('  FAIL  %s not in %s (not built?)' % (', '.join(missing), directory))
        print('%s: 0 passed, 1 failed' % name)
        return 1
    server = serve(directory, on_line, on_shot)
    port = server.server_address[1]
    url = 'http://127.0.0.1:%d/%s' % (port, page) + (query or ('?filter=' + urllib.parse.quote(filt) if filt else ''))
    profile = tempfile.mkdtemp(prefix='rbl-web-')
    log = open(os.path.join(directory, 'chromium-%s.log' % name if name != 'web' else 'chromium.log'), 'w')
    start = time.time()
    proc = subprocess.Popen([chromium()] + CHROMIUM_FLAGS + list(flags) + ['--user-data-dir=' + profile, '--remote-debugging-port=0', url],
                            stdout=log, stderr=subprocess.STDOUT)
    finished = done.wait(time_limit)
    proc.terminate()
    try:
        proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()
    server.shutdown()
    shutil.rmtree(profile, ignore_errors=True)
    elapsed = time.time() - start
    summary = [summary_re.match(l) for l in lines if summary_re.match(l)]
    if not finished:
        print('  FAIL  the page did not finish within %.0f s (see %s/chromium*.log)' % (time_limit, directory))
    if not summary:
        # The suite died before its closing line: count that as one failure, keep what passed
        passed = sum(1 for l in lines if l.startswith('  ok    '))
        failed = sum(1 for l in lines if l.startswith('  FAIL  ')) + 1
        print('  FAIL  suite did not finish (no summary line)')
        print('%s: %d passed, %d failed' % (name, passed, failed))
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
    if len(sys.argv) >= 4 and sys.argv[1] == 'page':
        mode = sys.argv[3]
        sys.exit(run_test(sys.argv[2], '', page='page_check.html', query='?mode=' + urllib.parse.quote(mode),
                          summary_re=re.compile(r'^page_%s: (\d+) passed, (\d+) failed$' % re.escape(mode)),
                          flags=['--window-size=1280,800', '--hide-scrollbars'] + sys.argv[4:], name='page_' + mode,
                          time_limit=float(os.environ.get('WEB_PAGE_TIMEOUT', '400'))))
    if len(sys.argv) >= 6 and sys.argv[1] == 'shot':
        sys.exit(run_shot(sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5]), int(sys.argv[6]) if len(sys.argv) > 6 else 5000))
    sys.exit(__doc__)
