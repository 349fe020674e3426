"""End-to-end: the first visit is never blank (issue #29):
index.html paints a loading screen without any script, the app replaces
it, and when the app cannot start the screen says what to do; a first
visit over a slow link; the files worker when it cannot load."""

import pytest
from selenium.webdriver.common.by import By

from conftest import DistServer, GzipOnTheFlyServer, record_figures
from test_app import ROOT, el, open_fresh, wait


def test_the_app_replaces_the_loading_screen(driver, base_url):
    open_fresh(driver, base_url)
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="loading"]'),
         message="the loading screen is gone once the app runs")
    assert el(driver, "ladder").is_displayed()


def test_a_blocked_app_leaves_the_loading_screen_saying_what_to_do(driver, base_url):
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.setBlockedURLs", {"urls": ["*.wasm"]})
    driver.get(base_url)
    loading = el(driver, "loading")
    assert "Hashigo" in loading.text and "Loading" in loading.text
    late = el(driver, "loading-late")
    assert float(late.value_of_css_property("opacity")) < 0.5, "not at once"
    wait(driver, lambda: float(late.value_of_css_property("opacity")) == 1.0, timeout=30,
         message="after a while it says what to do")
    assert "WebAssembly" in late.text


# The link: 1.6 Mbit/s down, 150 ms before each response.
SLOW_LINK = {"offline": False, "latency": 150, "downloadThroughput": 1_600_000 / 8,
             "uploadThroughput": 750_000 / 8}


def slow_first_visit(driver, served):
    """One first visit over the slow link: a new server on a port of its
    own is a new origin, so nothing is cached and no service worker
    answers (as a fresh profile). Its timeline: first words, app ready,
    each file fetched (asked at, arrived by, bytes sent, size)."""
    server = DistServer(["--brotli", "--gzip"]) if served == "brotli" else GzipOnTheFlyServer()
    try:
        driver.get(server.url)
        wait(driver, lambda: driver.execute_script(
            "return performance.getEntriesByName('hashigo-ready').length > 0"), timeout=60,
            message="the app marks itself ready")
    finally:
        server.stop()
    return driver.execute_script("""
        const at = (name) => performance.getEntriesByName(name)[0].startTime;
        const files = performance.getEntriesByType('resource').map((r) => ({
            name: new URL(r.name).pathname, sent: r.transferSize, size: r.decodedBodySize,
            start: r.startTime, end: r.responseEnd }));
        return { words: at('first-contentful-paint'), ready: at('hashigo-ready'), files };
    """)


@pytest.mark.parametrize("served,ready_within", [("brotli", 3000), ("gzip", 3500)])
def test_a_first_visit_over_a_slow_link(driver, served, ready_within):
    """Issue #53: a first visit over the slow link shows words within 1 s
    and is ready within 3.0 s served as scripts/serve.sh serves it (the
    build's brotli), within 3.5 s from a static host that compresses on
    the fly with gzip at level 6 and has no brotli. A shared machine can
    slow one load: the best of up to three fresh visits is the link's
    figure (each goes to figures.json for docs/performance.md). Each
    visit must also come compressed, need one wasm (the files worker
    waits for its first use), show words first, and ask for the wasm
    among its first six files (a browser's connections to one host over
    HTTP/1.1: a seventh waits for one to free)."""
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", SLOW_LINK)
    visits = []
    for _ in range(3):
        timeline = slow_first_visit(driver, served)
        files = timeline["files"]
        assert 0 < timeline["words"] < timeline["ready"]
        wasm = [f for f in files if f["name"].endswith("_bg.wasm")]
        assert len(wasm) == 1, f"the first screen loads one wasm: {files}"
        # Sent compressed: at most half of its size.
        assert 0 < wasm[0]["sent"] < wasm[0]["size"] / 2, wasm[0]
        before = [f["name"] for f in files if f["start"] <= wasm[0]["start"]]
        assert len(before) <= 6, f"the wasm waited for a connection behind {before}"
        visits.append(timeline)
        if timeline["words"] <= 1000 and timeline["ready"] <= ready_within:
            break
    best = min(visits, key=lambda v: v["ready"])
    wasm = next(f for f in best["files"] if f["name"].endswith("_bg.wasm"))
    figure = {
        "link": "1.6 Mbit/s down, 150 ms latency (CDP Network.emulateNetworkConditions)",
        "words_ms": round(best["words"]),
        "ready_ms": round(best["ready"]),
        "visits_ready_ms": [round(v["ready"]) for v in visits],
        "bytes_sent": sum(f["sent"] for f in best["files"]),
        "wasm_bytes_sent": wasm["sent"],
    }
    record_figures({f"first_visit_slow_link_{served}": figure})
    print(figure, best["files"])
    assert best["words"] <= 1000, f"words within 1 s: {figure}"
    assert best["ready"] <= ready_within, f"ready within {ready_within} ms: {figure}"


def test_when_the_files_worker_cannot_load_the_page_says_so(driver):
    # The page loaded, then the server gone before the worker's first use
    # (the service worker bypassed, as before it has kept the files).
    server = DistServer()
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.setBypassServiceWorker", {"bypass": True})
    open_fresh(driver, server.url)
    # The File menu's controls (a part, issue #53) were drawn while online.
    el(driver, "open-file")
    server.stop()
    el(driver, "open-file").send_keys(str(ROOT / "engine/tests/ladder/fixtures/openplc-named.xml"))
    try:
        wait(driver, lambda: "could not be loaded" in el(driver, "edit-message").text,
             message="the message line says the PLCopen tools did not load")
        assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]')
        # With the server back, the next try starts the worker again.
        server = DistServer(port=server.port)
        el(driver, "open-file").send_keys(str(ROOT / "engine/tests/ladder/fixtures/openplc-named.xml"))
        wait(driver, lambda: el(driver, "import-dialog"), message="the import goes on once it loads")
    finally:
        server.stop()


MACHINE_BOARDS = [("io86a", "io86a-terminal"), ("avr-plc", "avr-program-text"),
                  ("arduino-plc", "arduino-monitor"), ("soft-plc", "soft-board")]


def machine_arrivals(driver):
    """A first visit over the slow link (a new origin, as
    `slow_first_visit`), then each other machine chosen in turn: the
    milliseconds from choosing it to its panel drawn."""
    import time
    from selenium.webdriver.support.ui import Select
    server = DistServer(["--brotli", "--gzip"])
    arrivals = {}
    try:
        driver.get(server.url)
        wait(driver, lambda: driver.execute_script(
            "return performance.getEntriesByName('hashigo-ready').length > 0"), timeout=60,
            message="the app marks itself ready")
        fetched = driver.execute_script(
            "return performance.getEntriesByType('resource').map((r) => r.name)")
        assert not [f for f in fetched if "split_" in f], fetched
        for machine, board in MACHINE_BOARDS:
            start = time.monotonic()
            Select(el(driver, "machine")).select_by_value(machine)
            wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, f'[data-testid="{board}"]'),
                 timeout=30, message=f"{machine} arrives")
            arrivals[machine] = round((time.monotonic() - start) * 1000)
    finally:
        server.stop()
    return arrivals


def test_each_other_machine_arrives_over_the_slow_link(driver):
    """Issue #53: each machine but the first screen's is a part fetched
    when first shown, and over the slow link it is ready within 1.5 s of
    being chosen, the first time (while the service worker is still
    keeping the release's files). The first screen fetched none of them.
    As above, a shared machine can slow one visit: each machine's best
    of up to two fresh visits is its figure (figures.json)."""
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", SLOW_LINK)
    best = {}
    for _ in range(2):
        for machine, ms in machine_arrivals(driver).items():
            best[machine] = min(ms, best.get(machine, ms))
        if max(best.values()) <= 1500:
            break
    record_figures({"machine_arrival_slow_link_ms": best})
    print(best)
    slow = {m: ms for m, ms in best.items() if ms > 1500}
    assert not slow, f"ready within 1.5 s of being chosen: {best}"



def test_a_returning_visit_reads_its_saved_ladder_before_it_starts(driver, base_url):
    """The readers of a project's JSON are a part (issue #53): a visit
    with nothing saved never fetches them; a returning visit fetches them
    before the app is ready (the loading screen up meanwhile) and opens
    on its saved ladder."""
    from selenium.webdriver.support.ui import Select

    def reader_fetched():
        return [p for p in driver.execute_script(
            "return performance.getEntriesByType('resource').map(r => new URL(r.name).pathname)")
            if "split_reading" in p]

    open_fresh(driver, base_url)
    assert not reader_fetched(), "nothing saved: nothing to read"
    Select(el(driver, "example")).select_by_value("seed-test")
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")
    wait(driver, lambda: driver.execute_script(
        "return (localStorage.getItem('hashigo.ladder.minasec-u.v1') || '').includes('C0R')"),
        message="the ladder autosaved")
    driver.refresh()
    wait(driver, lambda: driver.execute_script(
        "return performance.getEntriesByName('hashigo-ready').length > 0"), message="ready")
    read = driver.execute_script("""
        const ready = performance.getEntriesByName('hashigo-ready')[0].startTime;
        const part = performance.getEntriesByType('resource')
            .find(r => r.name.includes('split_reading'));
        return part ? [part.responseEnd, ready] : null;""")
    assert read and read[0] <= read[1], f"the reader arrived before the app was ready: {read}"
    assert el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R", "the saved ladder is back"
