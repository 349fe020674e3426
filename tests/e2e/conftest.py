"""Fixtures: dist/ served on 127.0.0.1, and a headless Chromium driver."""

import functools
import http.server
import pathlib
import threading

import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service

ROOT = pathlib.Path(__file__).resolve().parents[2]
DIST = ROOT / "dist"
ARTIFACTS = pathlib.Path(__file__).resolve().parent / "artifacts"


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {
        **http.server.SimpleHTTPRequestHandler.extensions_map,
        ".wasm": "application/wasm",
        ".js": "text/javascript",
    }

    def log_message(self, *args):
        pass


@pytest.fixture(scope="session")
def base_url():
    assert (DIST / "index.html").exists(), "run trunk build --release first"
    handler = functools.partial(QuietHandler, directory=str(DIST))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_address[1]}"
    server.shutdown()


@pytest.fixture
def driver(tmp_path):
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
    yield drv
    drv.quit()


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
