"""End-to-end: the first five minutes, as a fresh-eyes review found them.
Every machine stands stopped until Run (its clock too), and then keeps
the wall's time; the phone's Tests dock leaves the ladder and its strip
usable; the timing chart opens on what was recorded and follows it; W
opens the Why? pane; an OR branch's contact deleted leaves no stub; the
phone's toolbar has no two look-alike icons. Screenshots go to
artifacts/first-minutes-*.png."""

import time

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import el, open_fresh, wait
from test_ladder import focus_ladder, keys, place

MACHINES = ["minasec-u", "io86a", "arduino-plc", "avr-plc", "soft-plc"]


def clock(driver):
    c = el(driver, "sim-time", reveal=False)
    return c.get_attribute("data-state"), int(c.get_attribute("data-ms"))


def choose(driver, machine):
    Select(el(driver, "machine")).select_by_value(machine)
    wait(driver, lambda: el(driver, "workbench").get_attribute("data-machine") == machine)


def test_every_machine_stands_stopped_until_run_then_keeps_the_walls_time(driver, base_url):
    open_fresh(driver, base_url)
    # A fresh profile: each machine stopped, its time at zero, also after
    # the others were shown.
    for machine in MACHINES + MACHINES[:2]:
        choose(driver, machine)
        time.sleep(0.5)
        assert clock(driver) == ("stopped", 0), (machine, clock(driver))
        assert el(driver, "run").get_attribute("aria-pressed") == "false", machine
    for machine in ["soft-plc", "avr-plc", "io86a"]:
        choose(driver, machine)
        el(driver, "run").click()
        wait(driver, lambda: clock(driver)[0] == "running", message=f"{machine} runs")
        start_ms, start = clock(driver)[1], time.monotonic()
        time.sleep(2)
        ran = (clock(driver)[1] - start_ms) / 1000 / (time.monotonic() - start)
        assert 0.7 < ran < 1.3, f"{machine}: simulated time at {ran:.2f}x the wall's"
        el(driver, "run").click()
        wait(driver, lambda: clock(driver)[0] == "stopped", message=f"{machine} stops")
        held = clock(driver)[1]
        time.sleep(0.4)
        assert clock(driver)[1] == held, f"{machine}: time stands still when stopped"


def test_deleting_an_or_branchs_contact_leaves_no_stub(driver, base_url):
    open_fresh(driver, base_url)
    el(driver, "new-ladder").click()
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    el(driver, "cell-0-0-0").click()
    keys(driver, Keys.DOWN)
    place(driver, Keys.F5, "X01", shift=True)
    links = "[data-testid=ladder] [class*=link-]"
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, links), message="the branch's link drawn")
    el(driver, "cell-0-1-0").click()
    keys(driver, Keys.DELETE)
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, links), message="no link left hanging")
    assert el(driver, "cell-0-0-9").get_attribute("data-device") == "Y00", "the rest stays"


def test_w_opens_the_why_pane_and_focuses_it(driver, base_url):
    open_fresh(driver, base_url)
    el(driver, "new-ladder").click()
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    el(driver, "run").click()
    el(driver, "dock-tab-watch").click()
    el(driver, "cell-0-0-9").click()
    keys(driver, "w")
    wait(driver, lambda: el(driver, "dock-tab-why", reveal=False).get_attribute("aria-selected") == "true",
         message="the Why? tab shown")
    head = wait(driver, lambda: el(driver, "why-head", reveal=False))
    assert head.is_displayed() and "Y00" in head.text, head.text
    wait(driver, lambda: driver.execute_script(
        "return document.querySelector('[data-testid=why-panel]').contains(document.activeElement)"),
        message="the answer takes the focus")
    # Escape: back to the ladder, where the cursor was.
    keys(driver, Keys.ESCAPE)
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "ladder")


def test_the_phones_toolbar_has_no_two_look_alike_buttons(tmp_path, base_url, artifacts):
    from test_screens import screen_driver

    driver = screen_driver(tmp_path, "phone")
    try:
        open_fresh(driver, base_url)
        shown = driver.execute_script(
            "return [...document.querySelectorAll('.ladder-toolbar button')]"
            ".filter(b => b.getClientRects().length)"
            ".map(b => [b.dataset.testid, b.innerText.trim(), b.title || '', !!b.querySelector('svg')])")
        faces = [(face, svg) for _, face, _, svg in shown]
        looks = [f"{face}|{svg}" for face, svg in faces]
        assert len(set(looks)) == len(looks), shown
        icons = [b for b in shown if b[3] or len(b[1]) <= 2]
        assert all(title for _, _, title, _ in icons), f"each icon names itself on hover: {icons}"
        el(driver, "new-ladder").screenshot(str(artifacts / "first-minutes-new-ladder.png"))
    finally:
        driver.quit()


def test_on_a_phone_an_exercises_tests_leave_the_ladder_and_its_strip_usable(tmp_path, base_url, artifacts):
    from test_screens import on_screen, screen_driver

    driver = screen_driver(tmp_path, "phone", first_visit=True)
    try:
        driver.get(base_url)
        wait(driver, lambda: el(driver, "start-exercise").is_displayed())
        el(driver, "start-exercise").click()
        wait(driver, lambda: el(driver, "start-exercise-0").is_displayed())
        el(driver, "start-exercise-0").click()
        wait(driver, lambda: el(driver, "exercise-task", reveal=False).is_displayed(),
             message="the exercise opens with its task in the Tests tab")
        # The Tests tab's name whole, not under the "?" beside the tabs.
        wait(driver, lambda: driver.execute_script(
            "const t = document.querySelector('[data-testid=dock-tab-tests]').getBoundingClientRect();"
            "const s = t && document.querySelector('.dock-tabs').getBoundingClientRect();"
            "return t.left >= s.left - 1 && t.right <= s.right + 1;"), message="the Tests tab whole")
        # The palette, the ladder and the strip of its inputs on screen,
        # above the sheet, without anything moved by hand.
        for testid in ["palette", "ladder", "io-strip"]:
            wait(driver, lambda: on_screen(driver, testid), message=f"{testid} on screen")
        driver.save_screenshot(str(artifacts / "first-minutes-phone-exercise.png"))
    finally:
        driver.quit()


def axis_scans(driver):
    import re
    return [int(n) for n in re.findall(r"scan (\d+)", el(driver, "chart-axis", reveal=False).text)]


def test_the_timing_chart_opens_on_what_was_recorded_and_follows_it(driver, base_url, artifacts):
    from test_ladder import seed_running

    driver.set_window_size(1366, 768)
    seed_running(driver, base_url, "1")
    el(driver, "input-X00").click()
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="started")
    el(driver, "input-X00").click()
    time.sleep(3)
    el(driver, "dock-tab-chart").click()
    # Seconds of the run in view, T0's pulses among them: not flat traces
    # of the last moment.
    t0 = wait(driver, lambda: el(driver, "chart-row-T0", reveal=False))
    wait(driver, lambda: int(t0.get_attribute("data-rises")) >= 2, message="T0's pulses in view")
    # All that was recorded (a few seconds' scans), from its first scan.
    first = int(el(driver, "timeline").get_attribute("min"))
    assert axis_scans(driver)[0] <= first + 1, (first, axis_scans(driver))
    shown = driver.execute_script(
        "const body = document.querySelector('[data-testid=dock-bottom] .dock-body').getBoundingClientRect();"
        "return [...document.querySelectorAll('.chart-name')].filter(r => {"
        "  const b = r.getBoundingClientRect(); return b.height > 0 && b.bottom <= body.bottom + 1; }).length;")
    assert shown >= 4, f"rows in view in the dock at 1366x768: {shown}"
    driver.save_screenshot(str(artifacts / "first-minutes-chart.png"))
    # It follows the newest scan while running.
    newest = axis_scans(driver)[-1]
    wait(driver, lambda: axis_scans(driver)[-1] > newest, message="the view follows the run")
    # A scan travelled to, before the view, is brought into it.
    el(driver, "pause").click()
    driver.execute_script(
        "const s = arguments[0]; s.value = String(arguments[1]);"
        "s.dispatchEvent(new Event('input', {bubbles: true}));", el(driver, "timeline"), first + 5)
    wait(driver, lambda: axis_scans(driver)[0] <= first + 5 <= axis_scans(driver)[-1],
         message=f"scan {first + 5} in view: {axis_scans(driver)}")
