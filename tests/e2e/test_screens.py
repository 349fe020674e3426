"""End-to-end: the page on every screen (issue #27). A laptop (1366x768), a
big screen (1920x1080), a touch tablet (820x1180) and a touch phone
(390x844, Chromium's mobile emulation): draw X00 -> Y00 (keys on desktops,
taps on touch), find the coil on screen, run it and drive it from the
panel (on desktops without scrolling the page), open every pane in view,
and never overflow sideways."""

import time

import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from conftest import as_returning_user
from test_app import ROOT, drawn, el, on, open_fresh, wait
from test_ladder import focus_ladder, place

SCREENS = {
    "laptop": (1366, 768, False),
    "desktop": (1920, 1080, False),
    "tablet": (820, 1180, True),
    "phone": (390, 844, True),
}


def screen_driver(tmp_path, name, first_visit=False):
    width, height, touch = SCREENS[name]
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--no-first-run", "--lang=en-US", f"--window-size={width},{height}",
                 f"--user-data-dir={tmp_path / 'profile'}"]:
        options.add_argument(flag)
    if touch:
        options.add_experimental_option("mobileEmulation", {
            "deviceMetrics": {"width": width, "height": height, "pixelRatio": 2, "touch": True}})
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    drv = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    drv.set_page_load_timeout(30)
    if not first_visit:
        as_returning_user(drv)
    return drv


@pytest.fixture(params=list(SCREENS))
def screen(request, tmp_path):
    drv = screen_driver(tmp_path, request.param)
    # The failure hook in conftest.py finds the driver under this name.
    request.node.funcargs["driver"] = drv
    yield request.param, drv
    drv.quit()


def rect(driver, testid):
    return driver.execute_script(
        "const b = document.querySelector(arguments[0]).getBoundingClientRect();"
        "return {x: b.x, y: b.y, w: b.width, h: b.height, vw: innerWidth, vh: innerHeight};",
        f'[data-testid="{testid}"]')


def on_screen(driver, testid):
    """Its centre is inside the window and it is what is drawn there (not
    clipped by a scrolling box, not under something else)."""
    return driver.execute_script(
        "const e = document.querySelector(arguments[0]); if (!e) return false;"
        "const b = e.getBoundingClientRect();"
        "const x = b.x + b.width / 2, y = b.y + b.height / 2;"
        "if (x < 0 || y < 0 || x >= innerWidth || y >= innerHeight) return false;"
        "const top = document.elementFromPoint(x, y); if (!top || !(top === e || e.contains(top))) return false;"
        # The rung labels stay on the left above the cells scrolled under them
        # (a cell of the ladder only: the phone's panel sheet covers them).
        "if (!e.closest('.ladder')) return true;"
        "return ![...document.querySelectorAll('.rung-head')].some(h => { const r = h.getBoundingClientRect();"
        "  return x >= r.left && x < r.right && y >= r.top && y < r.bottom; });",
        f'[data-testid="{testid}"]')


def no_sideways_overflow(driver):
    return driver.execute_script("return document.documentElement.scrollWidth <= innerWidth")


def tap_entry(driver, palette, device):
    el(driver, palette).click()
    chips = wait(driver, lambda: [b for b in driver.find_elements(
        By.CSS_SELECTOR, '[data-testid="device-options"] button') if b.text.split()[0] == device])
    # In the middle of the screen, clear of the sticky strip as a user
    # would scroll it.
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", chips[0])
    chips[0].click()
    el(driver, "device-ok").click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="device-input"]'))


def draw_contact_and_coil(driver, touch, contact, coil):
    """contact -> (coil) on the first rung: by taps on touch screens, by
    F5 / F7 on desktops."""
    if touch:
        el(driver, "cell-0-0-0").click()
        tap_entry(driver, "palette-no", contact)
        tap_entry(driver, "palette-coil", coil)
    else:
        focus_ladder(driver)
        place(driver, Keys.F5, contact)
        place(driver, Keys.F7, coil)


def run_and_drive(driver, touch, switch, lamp):
    """Run, then the panel's `switch` on screen and pressed, and its
    `lamp` lit and on screen; the page's scroll before the panel showed."""
    el(driver, "run").click()
    scrolled = driver.execute_script("return scrollY")
    show(driver, touch, "panel")
    if touch:
        # One tap showed the panel; on a phone it may be a flick away.
        driver.execute_script(f"document.querySelector('[data-testid={switch}]').scrollIntoView({{block: 'center'}})")
    wait(driver, lambda: on_screen(driver, switch), message="the input is on screen")
    el(driver, switch).click()
    wait(driver, lambda: on(driver, lamp), message=f"{lamp} follows {switch}")
    if touch:
        driver.execute_script(f"document.querySelector('[data-testid={lamp}]').scrollIntoView({{block: 'center'}})")
    assert on_screen(driver, lamp)
    return scrolled


def coil_testid(driver):
    coils = [c for c in driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-kind="coil"]')
             if c.get_attribute("data-device") == "Y00"]
    assert len(coils) == 1
    return coils[0].get_attribute("data-testid")


def show(driver, touch, tab):
    """The workbench has no view tabs (issue #45): the ladder, the panel
    and the tools share the screen; on a phone the panel is the bottom
    sheet's Panel tab, shown for "panel" and put away for the others."""
    tab_panel = driver.find_element(By.CSS_SELECTOR, '[data-testid="dock-tab-panel"]')
    if not tab_panel.is_displayed():
        return
    shown = tab_panel.get_attribute("aria-selected") == "true"
    if (tab == "panel") != shown:
        tab_panel.click()


def test_draw_run_and_drive_on_every_screen(screen, base_url, artifacts):
    name, driver = screen
    touch = SCREENS[name][2]
    open_fresh(driver, base_url)
    assert no_sideways_overflow(driver), "the page fits the width"
    el(driver, "new-ladder").click()
    draw_contact_and_coil(driver, touch, "X00", "Y00")
    coil = coil_testid(driver)
    assert coil.startswith("cell-0-0-")
    # The cursor went on past the coil; back on it, it is in view.
    if not touch:
        driver.switch_to.active_element.send_keys(Keys.ARROW_UP, Keys.END)
        wait(driver, lambda: on_screen(driver, coil), message="End shows the output column")
        driver.switch_to.active_element.send_keys(Keys.HOME)
        wait(driver, lambda: on_screen(driver, "cell-0-0-0"), message="Home shows the first column")
    el(driver, "zoom-fit").click()
    wait(driver, lambda: on_screen(driver, coil) and on_screen(driver, "cell-0-0-0"),
         message="fit width shows the whole rung")
    assert no_sideways_overflow(driver)

    scrolled = run_and_drive(driver, touch, "input-X00", "lamp-Y00")
    if not touch:
        assert on_screen(driver, coil), "the rung and the panel on screen together"
        assert driver.execute_script("return scrollY") == scrolled, "no page scroll needed"
    assert no_sideways_overflow(driver)
    driver.save_screenshot(str(artifacts / f"screen-{name}.png"))


@pytest.mark.parametrize("opener,pane", [
    ("projects-open", "projects"), ("find-open", "find"), ("keys", "keymap"),
])
def test_every_pane_opens_in_view_takes_the_focus_and_closes_on_escape(screen, base_url, opener, pane):
    name, driver = screen
    touch = SCREENS[name][2]
    open_fresh(driver, base_url)
    show(driver, touch, "tools")
    el(driver, opener).click()
    wait(driver, lambda: on_screen(driver, pane), message=f"{pane} opens in view")
    focused_inside = driver.execute_script(
        "const p = document.querySelector(arguments[0]);"
        "const d = p.closest('[role=dialog]') || p; return d.contains(document.activeElement);",
        f'[data-testid="{pane}"]')
    assert focused_inside, f"{pane} takes the focus"
    driver.switch_to.active_element.send_keys(Keys.ESCAPE)
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, f'[data-testid="{pane}"]'),
         message=f"Escape closes {pane}")
    assert no_sideways_overflow(driver)


def smallest_targets(driver):
    """The smallest height and width of the visible buttons and selects."""
    return driver.execute_script(
        "const hs = [], ws = [];"
        "for (const e of document.querySelectorAll('button, select')) {"
        "  const b = e.getBoundingClientRect(); if (!b.width || !b.height) continue;"
        "  if (getComputedStyle(e).visibility === 'hidden') continue; hs.push(b.height); ws.push(b.width); }"
        "return [Math.min(...hs), Math.min(...ws)];")


def test_the_tests_tab_opens_in_view(screen, base_url):
    name, driver = screen
    open_fresh(driver, base_url)
    el(driver, "tests-open").click()
    wait(driver, lambda: on_screen(driver, "tests"), message="the Tests tab opens in view")
    assert el(driver, "dock-tab-tests").get_attribute("aria-selected") == "true"
    assert no_sideways_overflow(driver)


def test_targets_are_big_enough_for_the_pointer(screen, base_url):
    name, driver = screen
    touch = SCREENS[name][2]
    open_fresh(driver, base_url)
    for tab in (["ladder", "panel"] if touch else [None]):
        if tab:
            show(driver, touch, tab)
        height, width = smallest_targets(driver)
        assert width >= 24 and height >= (44 if touch else 24), (tab, height, width)


def zoom_at(driver):
    return el(driver, "zoom-at").text


def test_ctrl_wheel_and_a_pinch_zoom_the_ladder(driver, base_url):
    open_fresh(driver, base_url)
    assert zoom_at(driver) == "100 %"
    wheel = ("document.querySelector('[data-testid=ladder]').dispatchEvent(new WheelEvent('wheel',"
             " {deltaY: arguments[0], ctrlKey: true, bubbles: true, cancelable: true}))")
    driver.execute_script(wheel, -100)
    wait(driver, lambda: zoom_at(driver) == "115 %", message="Ctrl+wheel up zooms in")
    driver.execute_script(wheel, 100)
    wait(driver, lambda: zoom_at(driver) == "100 %", message="and down zooms out")
    # Two fingers spread from 100 px apart to 150 px: 150 %.
    pinch = ("const l = document.querySelector('[data-testid=ladder]');"
             "const at = (type, id, x) => l.dispatchEvent(new PointerEvent(type, {pointerId: id,"
             " pointerType: 'touch', clientX: x, clientY: 400, bubbles: true}));"
             "at('pointerdown', 11, 300); at('pointerdown', 12, 400);"
             "at('pointermove', 12, 450); at('pointerup', 11, 300); at('pointerup', 12, 450);")
    driver.execute_script(pinch)
    wait(driver, lambda: zoom_at(driver) == "150 %", message="a pinch zooms")
    el(driver, "zoom-100").click()
    assert zoom_at(driver) == "100 %"


def contrast(a, b):
    """WCAG contrast of two CSS rgb() colours."""
    def lum(c):
        r, g, b = [int(x) / 255 for x in c[c.index("(") + 1:c.index(")")].split(",")[:3]]
        f = lambda v: v / 12.92 if v <= 0.03928 else ((v + 0.055) / 1.055) ** 2.4
        return 0.2126 * f(r) + 0.7152 * f(g) + 0.0722 * f(b)
    hi, lo = sorted([lum(a), lum(b)], reverse=True)
    return (hi + 0.05) / (lo + 0.05)


def test_focus_rings_stand_out_from_what_they_sit_on(driver, base_url):
    open_fresh(driver, base_url)
    for testid, backdrop in [("undo", "section.ladder-editor"), ("speed", "header.top")]:
        el(driver, testid)  # present
        driver.execute_script("document.querySelector(arguments[0]).focus()", f'[data-testid="{testid}"]')
        driver.switch_to.active_element.send_keys(Keys.SHIFT)  # keyboard focus: :focus-visible
        ring, behind = driver.execute_script(
            "const e = document.querySelector(arguments[0]);"
            "return [getComputedStyle(e).outlineColor, getComputedStyle(document.querySelector(arguments[1])).backgroundColor];",
            f'[data-testid="{testid}"]', backdrop)
        assert contrast(ring, behind) >= 3, (testid, ring, behind)


def test_the_import_dialog_takes_the_focus_and_gives_it_back(driver, base_url):
    from test_import import FBD, import_dialog
    import_dialog(driver, base_url, FBD, "the dialog, since lamp has no device")
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "import-dialog",
         message="the dialog has the focus")
    driver.switch_to.active_element.send_keys(Keys.ESCAPE)
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]'))
    assert driver.switch_to.active_element.get_attribute("data-testid") == "ladder"


def test_the_soft_plc_on_every_screen(screen, base_url, artifacts):
    """The soft PLC's board and variables pane (issue #31) fit every
    screen: %IX0.0 -> %QX0.0 drawn, run, driven from the board; then the
    parts example, its analog slider and gauge and its variables."""
    from selenium.webdriver.support.ui import Select
    name, driver = screen
    touch = SCREENS[name][2]
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("soft-plc")
    wait(driver, lambda: el(driver, "soft-board"))
    draw_contact_and_coil(driver, touch, "%IX0.0", "%QX0.0")
    scrolled = run_and_drive(driver, touch, "soft-input-IX0-0", "soft-lamp-QX0-0")
    if not touch:
        assert driver.execute_script("return scrollY") == scrolled, "no page scroll needed"
    assert no_sideways_overflow(driver)
    driver.save_screenshot(str(artifacts / f"screen-soft-{name}.png"))

    show(driver, touch, "ladder")
    Select(el(driver, "example")).select_by_value("parts")
    wait(driver, lambda: drawn(driver, "var-parts"))
    show(driver, touch, "panel")
    for testid in ["soft-analog-IW0", "soft-gauge-QW0", "var-level"]:
        el(driver, testid)  # its dock tab (the variables) or the phone's Panel sheet shown
        driver.execute_script(f"document.querySelector('[data-testid={testid}]').scrollIntoView({{block: 'center'}})")
        wait(driver, lambda: on_screen(driver, testid), message=f"{testid} on screen")
    assert no_sideways_overflow(driver)
    driver.save_screenshot(str(artifacts / f"screen-soft-parts-{name}.png"))


def test_the_cpu_view_on_every_screen(screen, base_url, artifacts):
    """Inside MINASEC-U (issue #33): the CPU view opens, its step button
    and blocks come on screen and step an edge, on every screen, with no
    sideways scrolling."""
    name, driver = screen
    touch = SCREENS[name][2]
    open_fresh(driver, base_url)
    show(driver, touch, "panel")
    el(driver, "mode-halt").click()
    opener = el(driver, "cpu-view-open")
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", opener)
    opener.click()
    # The diagram is a part fetched at the first opening (issue #53).
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="cpu-step-edge"]'),
         message="the CPU view's part loaded")
    for testid in ["cpu-step-edge", "cpu-block-pc", "cpu-block-counter", "cpu-strip"]:
        driver.execute_script(f"document.querySelector('[data-testid={testid}]').scrollIntoView({{block: 'center'}})")
        wait(driver, lambda: on_screen(driver, testid), message=f"{testid} on screen")
    driver.execute_script("document.querySelector('[data-testid=cpu-step-edge]').scrollIntoView({block: 'center'})")
    el(driver, "cpu-step-edge").click()
    wait(driver, lambda: el(driver, "cpu-phase").get_attribute("data-value") == "rising")
    assert el(driver, "cpu-block-accumulator").get_attribute("data-active") == "1"
    assert no_sideways_overflow(driver)
    driver.save_screenshot(str(artifacts / f"screen-cpu-{name}.png"))


def test_an_ld_files_digits_on_every_screen(screen, base_url, tmp_path, artifacts):
    """The soft PLC's 7-segment digits (issue #32) on every screen: the
    board's input pressed, the digits on screen showing the count."""
    from test_ldmicro import lit_segments, open_digits
    name, driver = screen
    touch = SCREENS[name][2]
    open_fresh(driver, base_url)
    open_digits(driver, tmp_path)
    show(driver, touch, "panel")
    driver.execute_script("document.querySelector('[data-testid=soft-input-IX0-0]').scrollIntoView({block: 'center'})")
    wait(driver, lambda: on_screen(driver, "soft-input-IX0-0"), message="the input on screen")
    el(driver, "soft-input-IX0-0").click()
    driver.execute_script("document.querySelector('[data-testid=soft-digits]').scrollIntoView({block: 'center'})")
    for digit in ["soft-digit-seg", "soft-digit-an"]:
        wait(driver, lambda: on_screen(driver, digit), message=f"{digit} on screen")
        wait(driver, lambda: lit_segments(driver, digit) == "bc", message=f"{digit} shows 1")
        box = rect(driver, digit)
        assert box["x"] >= 0 and box["x"] + box["w"] <= box["vw"], box
    assert no_sideways_overflow(driver)
    driver.save_screenshot(str(artifacts / f"screen-digits-{name}.png"))


def test_a_long_string_in_the_variables_pane_on_every_screen(screen, base_url, tmp_path, artifacts):
    """A STRING of 60 characters (LDmicro's STRING, issue #32) in the
    variables pane: cut to fit, its whole text in the title, no Set form;
    the page no wider than the screen."""
    from test_ldmicro import open_ld, var_value
    name, driver = screen
    touch = SCREENS[name][2]
    open_fresh(driver, base_url)
    text = "Line 1: " + "x" * 52
    codes = " ".join(str(ord(c)) for c in text)
    ld = "\n".join(["LDmicro0.2", "CYCLE=10000", "PROGRAM", "RUNG",
                    f"    STRING banner (none) {len(text)} {codes}", "END", ""])
    open_ld(driver, tmp_path, "banner.ld", ld, "banner")
    el(driver, "run").click()
    wait(driver, lambda: var_value(driver, "banner") == f"'{text}'", message="the text printed")
    show(driver, touch, "panel")
    driver.execute_script("document.querySelector('[data-testid=var-banner]').scrollIntoView({block: 'center'})")
    shown = driver.find_element(By.CSS_SELECTOR, '[data-testid="var-banner"] [data-testid="var-value"]')
    assert shown.get_attribute("title") == f"'{text}'"
    assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="var-banner"] [data-testid="var-set"]'), \
        "a STRING has no value to set: its text takes the room"
    box = driver.execute_script(
        "const r = arguments[0].getBoundingClientRect();"
        "return {x: r.x, w: r.width, vw: document.documentElement.clientWidth};", shown)
    assert box["x"] >= 0 and box["x"] + box["w"] <= box["vw"], box
    assert no_sideways_overflow(driver)
    driver.save_screenshot(str(artifacts / f"screen-string-{name}.png"))


def test_on_a_phone_the_device_entry_leaves_the_cell_and_the_task_in_view(tmp_path, base_url, artifacts):
    """The newcomer review's phone finding: with an exercise's task up in
    the sheet, the device entry pushed the ladder under the sheet and was
    itself cut off by it. It floats at the top of the screen now: the
    entry whole above the sheet, the cell being filled still seen."""
    import re
    page = (ROOT / "web/start/en.html").read_text(encoding="utf-8")
    fragment = next(m.group(1) for m in re.finditer(r'<a href="\./#([^"]+)"[^>]*>([^<]+)<', page)
                    if m.group(2).startswith("Forward and reverse"))
    driver = screen_driver(tmp_path, "phone")
    try:
        driver.get(f"{base_url}/#{fragment}")
        wait(driver, lambda: el(driver, "exercise-task").is_displayed(), message="the task in the sheet")
        el(driver, "cell-0-0-0").click()
        el(driver, "palette-no").click()
        wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="device-options"] button'))
        time.sleep(0.5)
        driver.save_screenshot(str(artifacts / "phone-device-entry-with-task.png"))
        box = lambda selector: driver.execute_script(
            "const r = document.querySelector(arguments[0]).getBoundingClientRect();"
            "return {top: r.top, bottom: r.bottom};", selector)
        entry, sheet = box(".entry-bar"), box('[data-testid="dock-bottom"]')
        assert 0 <= entry["top"] and entry["bottom"] <= sheet["top"], (entry, sheet)
        seen = driver.execute_script("""
            const cell = document.querySelector('[data-testid="cell-0-0-0"]');
            const r = cell.getBoundingClientRect();
            const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
            return hit !== null && cell.contains(hit);""")
        assert seen, "the cell being filled is seen, not under the entry or the sheet"
        assert el(driver, "exercise-task").is_displayed()
    finally:
        driver.quit()
