"""Fixtures: dist/ served on 127.0.0.1 as scripts/serve.sh serves it
(http-server with the build's precompressed files), and a headless
Chromium driver."""

import json
import pathlib
import socket
import subprocess
import time
import urllib.request

import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service

ROOT = pathlib.Path(__file__).resolve().parents[2]
DIST = ROOT / "dist"
ARTIFACTS = pathlib.Path(__file__).resolve().parent / "artifacts"


SERVER = ROOT / ".tools" / "node_modules" / ".bin" / "http-server"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class DistServer:
    """dist/ served as scripts/serve.sh serves it: http-server with the
    build's .br / .gz when the browser accepts them (`encodings`: the
    flags, e.g. only ["--gzip"] as a host without brotli)."""

    def __init__(self, encodings=("--brotli", "--gzip"), port=None):
        assert (DIST / "index.html").exists(), "run trunk build --release first"
        assert SERVER.exists(), "run scripts/setup.sh (it installs http-server)"
        port = port or free_port()
        self.port = port
        self.process = subprocess.Popen(
            [str(SERVER), str(DIST), "-a", "127.0.0.1", "-p", str(port), *encodings, "-s", "-c-1"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.url = f"http://127.0.0.1:{port}"
        deadline = time.monotonic() + 20
        while True:
            try:
                urllib.request.urlopen(self.url, timeout=1).close()
                return
            except OSError:
                if time.monotonic() > deadline or self.process.poll() is not None:
                    self.process.kill()
                    raise
                time.sleep(0.1)

    def stop(self):
        self.process.terminate()
        self.process.wait(timeout=10)


class GzipOnTheFlyServer:
    """dist/ served as a static host that compresses each response on the
    fly with gzip at level 6 and has no brotli (issue #53's second host):
    the build's precompressed .gz and .br are not used. Like nginx's gzip
    it streams what it has compressed so far."""

    TYPES = {".wasm": "application/wasm", ".js": "text/javascript", ".mjs": "text/javascript",
             ".css": "text/css", ".html": "text/html; charset=utf-8", ".json": "application/json",
             ".svg": "image/svg+xml", ".webmanifest": "application/manifest+json",
             ".png": "image/png", ".ico": "image/x-icon"}

    def __init__(self):
        import http.server
        import threading
        import zlib

        assert (DIST / "index.html").exists(), "run trunk build --release first"
        types = self.TYPES

        class Handler(http.server.BaseHTTPRequestHandler):
            def do_GET(self):
                path = self.path.split("?", 1)[0].split("#", 1)[0]
                file = (DIST / path.lstrip("/")).resolve()
                if path.endswith("/"):
                    file = file / "index.html"
                if DIST.resolve() not in file.parents or not file.is_file():
                    self.send_error(404)
                    return
                body = file.read_bytes()
                headers = {"Content-Type": types.get(file.suffix, "application/octet-stream"),
                           "Cache-Control": "no-cache"}
                squeeze = "gzip" in self.headers.get("Accept-Encoding", "") and file.suffix != ".png"
                if squeeze:
                    headers["Content-Encoding"] = "gzip"
                else:
                    headers["Content-Length"] = str(len(body))
                self.send_response(200)
                for k, v in headers.items():
                    self.send_header(k, v)
                self.end_headers()
                if not squeeze:
                    self.wfile.write(body)
                    return
                # Sent as it is compressed, as nginx's gzip sends it (no
                # Content-Length; the response ends when the connection
                # closes): the first bytes leave at once, not after the
                # whole file has been compressed.
                squeezer = zlib.compressobj(6, zlib.DEFLATED, 16 + zlib.MAX_WBITS)
                for at in range(0, len(body), 16 * 1024):
                    self.wfile.write(squeezer.compress(body[at:at + 16 * 1024]))
                    self.wfile.flush()
                self.wfile.write(squeezer.flush())

            def log_message(self, *args):
                pass

        self.server = http.server.ThreadingHTTPServer(("127.0.0.1", free_port()), Handler)
        self.url = f"http://127.0.0.1:{self.server.server_address[1]}"
        threading.Thread(target=self.server.serve_forever, daemon=True).start()

    def stop(self):
        self.server.shutdown()
        self.server.server_close()


@pytest.fixture(scope="session")
def base_url():
    server = DistServer()
    yield server.url
    server.stop()


# Every test but the start screen's own opens the page as a user who has
# closed the start screen (issue #47): the key is set before the page's
# script runs, on every page the browser opens.
RETURNING_USER = "try { localStorage.setItem('hashigo.start', 'closed'); } catch (e) {}"


def as_returning_user(drv):
    drv.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": RETURNING_USER})


def pytest_configure(config):
    config.addinivalue_line("markers", "first_visit: the page as a fresh profile sees it, start screen and all")


@pytest.fixture
def driver(tmp_path, request):
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in [
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-dev-shm-usage",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--no-first-run",
        "--window-size=1400,1000",
        "--lang=en-US",
        f"--user-data-dir={tmp_path / 'profile'}",
    ]:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    drv = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    drv.set_page_load_timeout(30)
    if request.node.get_closest_marker("first_visit") is None:
        as_returning_user(drv)
    yield drv
    drv.quit()


def record_figures(new):
    """Adds `new` to artifacts/figures.json (the measured figures that
    docs/performance.md and the README quote), keeping the others."""
    ARTIFACTS.mkdir(exist_ok=True)
    path = ARTIFACTS / "figures.json"
    figures = json.loads(path.read_text()) if path.exists() else {}
    figures |= new
    path.write_text(json.dumps(figures, indent=2) + "\n")
    return figures


@pytest.fixture(scope="session")
def artifacts():
    ARTIFACTS.mkdir(exist_ok=True)
    return ARTIFACTS


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    """On a failure: the page's screenshot goes to artifacts/ and its
    console into the report, so a failure seen once in CI can be read."""
    outcome = yield
    report = outcome.get_result()
    drv = item.funcargs.get("driver") if report.when == "call" and report.failed else None
    if drv is None:
        return
    try:
        ARTIFACTS.mkdir(exist_ok=True)
        shot = ARTIFACTS / f"failed-{item.name}.png"
        drv.save_screenshot(str(shot))
        console = "\n".join(f"{e['level']} {e['message']}" for e in drv.get_log("browser"))
        report.sections.append(("browser console", console or "(empty)"))
        report.sections.append(("screenshot", str(shot)))
    except Exception as e:  # the browser may be gone; the failure stands
        report.sections.append(("diagnostics", f"not taken: {e}"))
