"""End-to-end: the workbench (issue #45) on a laptop (1366x768), a big
screen (1920x1080), a touch tablet (820x1180) and a touch phone (390x844),
for all five machines: a rung of a normally-open contact, a normally-closed
contact and a coil drawn with F5, F6, F7 (by taps on touch) shows its coil
in view at the default zoom with labels of at least 11 px as rendered; on
desktops the page does not scroll and Run, the input and the lamp work from
one screen; the phone presses the input on the strip beside the ladder and
sees the coil powered; the clock stands still while the machine is
stopped."""

import time

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import el, on, open_fresh, wait
from test_ladder import focus_ladder, place
from test_screens import SCREENS, no_sideways_overflow, on_screen, screen, tap_entry  # noqa: F401 (screen: a fixture)

# Each machine's names for X00, X01, Y00, and its panel's switch and lamp
# (the AVR PLC's panel names its bits after the program it runs).
MACHINES = {
    "minasec-u": ("X00", "X01", "Y00", "input-X00", "lamp-Y00"),
    "io86a": ("X00", "X01", "Y00", "io86a-input-X00", "io86a-lamp-Y00"),
    "arduino-plc": ("X000", "X001", "Y000", "arduino-input-X000", "arduino-lamp-Y000"),
    "avr-plc": ("R0.0", "R0.1", "R1.0", None, None),
    "soft-plc": ("%IX0.0", "%IX0.1", "%QX0.0", "soft-input-IX0-0", "soft-lamp-QX0-0"),
}


def page_scrolls(driver):
    return driver.execute_script(
        "const d = document.documentElement; return d.scrollHeight > innerHeight + 1 || d.scrollWidth > innerWidth + 1")


def cell_of(driver, device, kind):
    cells = [c for c in driver.find_elements(By.CSS_SELECTOR, f'[data-testid="ladder"] [data-kind="{kind}"]')
             if c.get_attribute("data-device") == device]
    assert len(cells) == 1, (device, kind, len(cells))
    return cells[0].get_attribute("data-testid")


def smallest_label_px(driver, testid):
    """The smallest rendered font size (px, after the ladder's zoom) of the
    texts inside the cell."""
    return driver.execute_script(
        "const c = document.querySelector(arguments[0]); let least = 1e9;"
        "const zoom = (el) => { let z = 1; for (let e = el; e; e = e.parentElement) {"
        "  const v = parseFloat(getComputedStyle(e).zoom); if (v) z *= v; } return z; };"
        "for (const e of [c, ...c.querySelectorAll('*')]) {"
        "  if (![...e.childNodes].some(n => n.nodeType === 3 && n.textContent.trim())) continue;"
        "  least = Math.min(least, parseFloat(getComputedStyle(e).fontSize) * zoom(e)); }"
        "return least;", f'[data-testid="{testid}"]')


def draw_rung(driver, touch, no, nc, coil):
    if touch:
        el(driver, "cell-0-0-0").click()
        tap_entry(driver, "palette-no", no)
        tap_entry(driver, "palette-nc", nc)
        tap_entry(driver, "palette-coil", coil)
    else:
        focus_ladder(driver)
        place(driver, Keys.F5, no)
        place(driver, Keys.F6, nc)
        place(driver, Keys.F7, coil)


def panel_io(driver, machine):
    """The panel's switch for X00 and lamp for Y00 (the AVR PLC's from the
    rows its panel shows for the program's bits)."""
    _, _, _, switch, lamp = MACHINES[machine]
    if switch:
        return switch, lamp
    rows = wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid^="avr-input-"]'))
    names = [r.get_attribute("data-testid")[len("avr-input-"):] for r in rows]
    x00 = next(n for n in names if "0" in n and n.replace(".", "_").endswith(("0_0", "0.0")))
    y00 = next(n for n in names if n.replace(".", "_").endswith("1_0"))
    return f"avr-input-{x00}", f"avr-lamp-{y00}"


def clock_ms(driver):
    return int(el(driver, "sim-time").get_attribute("data-ms"))


@pytest.mark.parametrize("machine", list(MACHINES))
def test_a_rung_in_view_run_and_driven_from_one_screen(screen, base_url, artifacts, machine):
    name, driver = screen
    touch = SCREENS[name][2]
    phone = name == "phone"
    no, nc, coil, _, _ = MACHINES[machine]
    open_fresh(driver, base_url)
    if machine != "minasec-u":
        Select(el(driver, "machine")).select_by_value(machine)
        wait(driver, lambda: el(driver, "workbench").get_attribute("data-machine") == machine)
    el(driver, "new-ladder").click()
    draw_rung(driver, touch, no, nc, coil)
    coil_cell = cell_of(driver, coil, "coil")
    assert el(driver, "zoom-at").text == "100 %", "the default zoom"
    wait(driver, lambda: on_screen(driver, coil_cell) and on_screen(driver, "cell-0-0-0"),
         message="the whole rung, rail to coil, in view")
    for cell in ["cell-0-0-0", cell_of(driver, nc, "nc"), coil_cell]:
        assert smallest_label_px(driver, cell) >= 11, (cell, smallest_label_px(driver, cell))
    if not touch:
        assert not page_scrolls(driver), "the page itself does not scroll"

    # Every machine stands stopped until Run (the AVR PLC powered off):
    # simulated time stands still.
    assert el(driver, "sim-time").get_attribute("data-state") == "stopped", "stopped until Run"
    before = clock_ms(driver)
    time.sleep(0.3)
    assert clock_ms(driver) == before, "no time passes while stopped"
    assert el(driver, "run").get_attribute("aria-pressed") == "false", "Run writes the drawing"

    el(driver, "run").click()
    wait(driver, lambda: el(driver, "sim-time").get_attribute("data-state") == "running", message="runs")
    wait(driver, lambda: clock_ms(driver) > before, message="time runs while running")
    if phone:
        # The strip beside the ladder: X00 pressed, Y00's coil seen powered.
        strip_in = f"strip-in-{no}"
        wait(driver, lambda: on_screen(driver, strip_in), message="the strip's input on screen")
        el(driver, strip_in).click()
        wait(driver, lambda: el(driver, coil_cell).get_attribute("data-powered") == "1",
             message="the coil powered")
        assert on_screen(driver, coil_cell) and on_screen(driver, strip_in), "one screen"
        wait(driver, lambda: el(driver, f"strip-out-{coil}").get_attribute("data-on") == "1")
    else:
        switch, lamp = panel_io(driver, machine)
        if touch:
            driver.execute_script(f"document.querySelector('[data-testid=\"{switch}\"]').scrollIntoView({{block: 'center'}})")
        wait(driver, lambda: on_screen(driver, switch), message="the input on screen")
        el(driver, switch).click()
        wait(driver, lambda: on(driver, lamp), message=f"{lamp} follows {switch}")
        wait(driver, lambda: el(driver, coil_cell).get_attribute("data-powered") == "1",
             message="the coil powered")
        if not touch:
            assert on_screen(driver, lamp) and on_screen(driver, coil_cell), "ladder and lamp on one screen"
            assert not page_scrolls(driver)
    assert no_sideways_overflow(driver)
    driver.save_screenshot(str(artifacts / f"workbench-{machine}-{name}.png"))

    # Stop: the clock stands still, in the app bar's one state.
    el(driver, "run").click()
    wait(driver, lambda: el(driver, "sim-time").get_attribute("data-state") == "stopped", message="stops")
    stopped_at = clock_ms(driver)
    time.sleep(0.4)
    assert clock_ms(driver) == stopped_at, "time stands still while stopped"


def test_pause_holds_time_and_the_docks_remember_their_sizes(driver, base_url):
    driver.set_window_size(1366, 768)
    open_fresh(driver, base_url)
    el(driver, "run").click()
    wait(driver, lambda: el(driver, "sim-time").get_attribute("data-state") == "running")
    el(driver, "pause").click()
    wait(driver, lambda: el(driver, "sim-time").get_attribute("data-state") == "paused")
    held = clock_ms(driver)
    time.sleep(0.4)
    assert clock_ms(driver) == held, "paused: time stands still"
    el(driver, "pause").click()
    wait(driver, lambda: clock_ms(driver) > held, message="resumed")

    # A splitter moved by keys, the tools dock collapsed: kept over a reload.
    splitter = el(driver, "splitter-right")
    width = float(splitter.get_attribute("aria-valuenow"))
    splitter.send_keys(Keys.ARROW_LEFT, Keys.ARROW_LEFT)
    assert float(el(driver, "splitter-right").get_attribute("aria-valuenow")) == width + 32
    el(driver, "dock-tab-tests").click()
    el(driver, "dock-bottom-toggle").click()
    wait(driver, lambda: el(driver, "dock-bottom", reveal=False).get_attribute("data-open") == "false")
    driver.refresh()
    wait(driver, lambda: el(driver, "mode-run"))
    assert float(el(driver, "splitter-right", reveal=False).get_attribute("aria-valuenow")) == width + 32
    assert el(driver, "dock-bottom", reveal=False).get_attribute("data-open") == "false"
    el(driver, "dock-tab-tests").click()
    wait(driver, lambda: el(driver, "dock-bottom", reveal=False).get_attribute("data-open") == "true")
    assert el(driver, "dock-tab-tests").get_attribute("aria-selected") == "true"


def test_the_menus_hold_the_files_and_the_palette_finds_a_part(driver, base_url):
    driver.set_window_size(1366, 768)
    open_fresh(driver, base_url)
    assert not el(driver, "save-json", reveal=False).is_displayed(), "in the File menu"
    el(driver, "menu-file").click()
    assert el(driver, "save-json", reveal=False).is_displayed()
    driver.find_element(By.TAG_NAME, "body").send_keys(Keys.ESCAPE)
    el(driver, "menu-file").send_keys(Keys.ESCAPE)
    wait(driver, lambda: not el(driver, "save-json", reveal=False).is_displayed(), message="Escape closes it")
    Select(el(driver, "machine")).select_by_value("soft-plc")
    wait(driver, lambda: el(driver, "workbench").get_attribute("data-machine") == "soft-plc")
    palette = el(driver, "palette")
    assert palette.size["height"] <= driver.execute_script("return innerHeight"), "never taller than the screen"
    el(driver, "palette-search").send_keys("counter")
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="palette-no"]'))
    assert el(driver, "palette-ctu").is_displayed()


def row_tops(driver, selector):
    return driver.execute_script(
        "return [...document.querySelectorAll(arguments[0])].map(e => Math.round(e.getBoundingClientRect().top))",
        selector)


@pytest.mark.parametrize("lang", ["en", "ja"])
def test_on_a_laptop_the_app_bar_is_one_row_and_box_names_one_line(driver, base_url, lang):
    """At 1366x768 the app bar keeps one row in both languages (Japanese
    labels are wider), on the machine with the longest name too; the
    palette's box names ([R_TRIG]) keep one line in its column."""
    driver.set_window_size(1366, 768)
    open_fresh(driver, base_url, lang)
    for machine in ["minasec-u", "soft-plc"]:
        Select(el(driver, "machine")).select_by_value(machine)
        wait(driver, lambda: el(driver, "share", reveal=False).is_displayed())
        bar = ["[data-testid='run']", "[data-testid='pause']", "[data-testid='speed']",
               "[data-testid='sim-time']", "[data-testid='share']", "[data-testid='machine']"]
        mids = driver.execute_script(
            "return arguments[0].map(s => { const r = document.querySelector(s).getBoundingClientRect();"
            " return Math.round(r.top + r.height / 2); })", bar)
        assert max(mids) - min(mids) <= 6, (machine, lang, dict(zip(bar, mids)))
        # The lines each name's text takes (its line boxes' distinct tops).
        lines = driver.execute_script(
            "return [...document.querySelectorAll('.palette-item')].filter(e => e.textContent.includes('TRIG'))"
            ".map(e => { const r = document.createRange(); r.selectNodeContents(e);"
            " return [e.textContent, new Set([...r.getClientRects()].map(x => Math.round(x.top))).size]; })")
        assert lines, "the palette has the edge boxes"
        assert all(n == 1 for _, n in lines), (machine, lines)


def test_each_tools_tab_keeps_its_own_scroll(driver, base_url):
    """Regression (the eighth session's newcomer review): the tools dock's
    panels share one scrolling body, so a tab opened scrolled to where the
    last one was (the plant's drawing out of view after a long Tests
    pane). Each tab now keeps its own scroll."""
    from test_plant import choose
    open_fresh(driver, base_url)
    Select(el(driver, "example")).select_by_value("seed-test")
    wait(driver, lambda: "ST   C0R" in el(driver, "il-listing").text, message="the listing's lines")
    body = driver.find_element(By.CSS_SELECTOR, '[data-testid="dock-bottom"] .dock-body')
    top = lambda: driver.execute_script("return arguments[0].scrollTop", body)
    driver.execute_script("arguments[0].scrollTop = arguments[0].scrollHeight", body)
    wait(driver, lambda: top() > 40, message="the listing scrolled to its end")
    left_at = top()
    choose(driver, "conveyor")
    tall = driver.execute_script("return arguments[0].scrollHeight - arguments[0].clientHeight", body)
    assert tall >= left_at, "the plant's panel is taller than the dock, or the test shows nothing"
    wait(driver, lambda: top() == 0, message="the plant's panel opens at its top")
    el(driver, "dock-tab-listing").click()
    wait(driver, lambda: top() == left_at, message="the listing is back where it was left")
