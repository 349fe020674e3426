"""End-to-end: a ladder read at a glance (issue #46): contacts lit by
conduction (`data-conducts`), the old colouring by device value as a
remembered View setting, a box's whole text on focus, the timing chart's
values written in their bands."""

import re

import pytest
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import el, open_fresh, wait
from test_ladder import focus_ladder, place, seed_running
from test_screens import screen_driver
from test_soft import choose_soft


def close_menu(driver):
    """Any open menu closed again, as a second press on its button does
    (a control chosen inside a menu leaves it open)."""
    shut = '[aria-haspopup][aria-expanded="true"], [data-testid="menus"][aria-expanded="true"]'
    driver.execute_script("for (const b of document.querySelectorAll(arguments[0])) b.click();", shut)
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, shut), message="menus closed")


def conducts(driver, cell):
    return el(driver, cell).get_attribute("data-conducts")


def lit(driver, cell):
    return "lit" in el(driver, cell).get_attribute("class").split()


def by_value(driver):
    return el(driver, "view-colour-by-value").get_attribute("aria-pressed") == "true"


def test_minasec_contacts_are_lit_while_closed_and_the_old_colouring_is_kept(driver, base_url):
    # The seed: X00 (NO, start) and X01 (NC, stop) in series to Y00.
    seed_running(driver, base_url, "max")
    no, nc = "cell-0-0-0", "cell-0-0-1"
    assert el(driver, nc).get_attribute("data-on") == "0", "X01 off"
    wait(driver, lambda: conducts(driver, nc) == "1", message="an NC contact whose input is off conducts")
    assert conducts(driver, no) == "0", "an NO contact whose input is off does not"
    assert lit(driver, nc) and not lit(driver, no)
    assert conducts(driver, "cell-0-0-9") is None, "a coil has no conduction"
    # Running, a cell's name says where it is and what; its live state is
    # said for the cell under the cursor, and for every cell once paused.
    assert el(driver, no).get_attribute("aria-selected") == "true", "the cursor starts there"
    wait(driver, lambda: el(driver, no).get_attribute("aria-label").endswith("X00, off, open"),
         message="the cursor's cell says its state")
    label = el(driver, nc).get_attribute("aria-label")
    assert label == "rung 1, row 1, column 2: normally closed contact X01", label
    el(driver, "pause").click()
    wait(driver, lambda: el(driver, nc).get_attribute("aria-label").endswith("off, closed"),
         message="paused: every cell says its state")
    el(driver, "pause").click()
    el(driver, "input-X00").click()
    el(driver, "input-X01").click()
    wait(driver, lambda: conducts(driver, no) == "1" and conducts(driver, nc) == "0", message="they swap")
    assert lit(driver, no) and not lit(driver, nc)
    # The old colouring: by the devices' values; the conduction stays said.
    assert not by_value(driver)
    el(driver, "view-colour-by-value").click()
    wait(driver, lambda: lit(driver, nc), message="X01 on: lit by value")
    assert lit(driver, no) and conducts(driver, nc) == "0"
    el(driver, "input-X01").click()
    wait(driver, lambda: conducts(driver, nc) == "1")
    assert not lit(driver, nc), "closed but its device off: unlit by value"
    # Kept over a reload.
    driver.refresh()
    wait(driver, lambda: el(driver, "cell-0-0-1").get_attribute("data-device") == "X01")
    assert by_value(driver)
    run_drawing(driver)
    wait(driver, lambda: conducts(driver, nc) == "1", message="running again")
    assert not lit(driver, nc)
    el(driver, "view-colour-by-value").click()
    wait(driver, lambda: lit(driver, nc))
    driver.refresh()
    wait(driver, lambda: el(driver, "cell-0-0-1").get_attribute("data-device") == "X01")
    assert not by_value(driver)


def run_drawing(driver):
    """Run pressed: the drawing written and started (stopped first when
    the machine already runs, the drawing not yet written)."""
    if el(driver, "run").get_attribute("data-running") == "true":
        el(driver, "run").click()
        wait(driver, lambda: el(driver, "run").get_attribute("data-running") == "false")
    el(driver, "run").click()
    wait(driver, lambda: el(driver, "run").get_attribute("data-running") == "true")


def test_soft_plc_contacts_are_lit_while_closed(driver, base_url):
    choose_soft(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "%IX0.0")
    place(driver, Keys.F6, "%IX0.0")
    place(driver, Keys.F7, "%QX0.0")
    run_drawing(driver)
    no, nc = "cell-0-0-0", "cell-0-0-1"
    wait(driver, lambda: conducts(driver, nc) == "1", message="NC of an input that is off: closed")
    assert conducts(driver, no) == "0" and el(driver, no).get_attribute("data-on") == "0"
    assert lit(driver, nc) and not lit(driver, no)
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: conducts(driver, no) == "1" and conducts(driver, nc) == "0", message="they swap")
    assert lit(driver, no) and not lit(driver, nc)
    assert el(driver, nc).get_attribute("data-on") == "1", "the device's own value stays on the cell"


def test_a_boxs_whole_text_shows_on_focus_and_in_its_name(driver, base_url):
    choose_soft(driver, base_url)
    Select(el(driver, "example")).select_by_value("parts")
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-kind="box"]'))
    boxes = driver.find_elements(By.CSS_SELECTOR, '[data-kind="box"]')
    # The box with the longest text.
    cell = max(boxes, key=lambda b: len(b.get_attribute("title") or ""))
    whole = cell.get_attribute("title")
    assert len(whole) > 20, whole
    assert whole in cell.get_attribute("aria-label")
    full = cell.find_element(By.CSS_SELECTOR, '[data-testid="box-whole"]')
    assert not full.is_displayed(), "shown only on hover or focus"
    cell.click()
    assert cell.get_attribute("aria-selected") == "true"
    wait(driver, full.is_displayed, message="the whole text on focus")
    assert full.text == whole
    cut = driver.execute_script(
        "const e = arguments[0], r = e.getBoundingClientRect();"
        "const l = document.querySelector('[data-testid=ladder]').getBoundingClientRect();"
        "const rung = e.closest('.rung');"
        "return e.scrollWidth > e.clientWidth + 1 || e.scrollHeight > e.clientHeight + 1"
        " || r.right > Math.min(innerWidth, l.right) + 1 || r.left < l.left - 1"
        " || getComputedStyle(rung).contentVisibility === 'auto';", full)
    assert not cut, "the whole text is not cut"


def test_the_chart_writes_a_counters_value_in_its_band(driver, base_url):
    seed_running(driver, base_url, "max")
    el(driver, "input-X00").click()
    el(driver, "dock-tab-chart").click()
    el(driver, "chart-add").send_keys("C0.v", Keys.ENTER)
    wait(driver, lambda: el(driver, "chart-row-C0.v"))
    assert el(driver, "chart-row-C0.v").get_attribute("data-shape") == "bands"
    # Read in one go: the chart shows all that was recorded and rewrites
    # its bands as the run goes on.
    texts = lambda: [int(t) for t in driver.execute_script(
        "return [...document.querySelectorAll('.chart-band-text[data-row=\"C0.v\"]')].map(e => e.textContent)")
        if re.fullmatch(r"\d+", t)]
    wait(driver, lambda: any(v > 0 for v in texts()), timeout=30, message="a count written in its band")
    values = texts()
    # It counts up, back to 0 only at its reset (C0R), which the whole
    # recording in view may show.
    assert all(b > a or b <= 1 for a, b in zip(values, values[1:])), f"a counter counts up: {values}"
    # The bits are steps, not bands.
    assert el(driver, "chart-row-Y00").get_attribute("data-shape") == "bits"
    axis = el(driver, "chart-axis").text
    assert "Time" in axis, axis


def js_click(driver, testid):
    driver.execute_script("arguments[0].click()", el(driver, testid))


@pytest.mark.parametrize("name", ["laptop", "phone"])
def test_screenshots_of_a_running_ladder_and_its_chart(tmp_path, base_url, artifacts, name):
    """Looked at by hand: contacts lit by conduction, the marks of their
    devices' values, a box's whole text, the chart's bands (issue #46)."""
    drv = screen_driver(tmp_path, name)
    try:
        open_fresh(drv, base_url)
        Select(el(drv, "example")).select_by_value("seed-test")
        wait(drv, lambda: el(drv, "cell-4-0-9").get_attribute("data-device") == "C0R")
        close_menu(drv)
        js_click(drv, "run")
        js_click(drv, "input-X00")
        wait(drv, lambda: conducts(drv, "cell-0-0-0") == "1")
        js_click(drv, "dock-tab-chart")
        el(drv, "chart-add").send_keys("C0.v", Keys.ENTER)
        wait(drv, lambda: drv.find_elements(By.CSS_SELECTOR, '.chart-band-text[data-row="C0.v"]'),
             timeout=30, message="the count in its band")
        drv.execute_script("document.querySelector('[data-testid=ladder]').scrollIntoView()")
        drv.save_screenshot(str(artifacts / f"glance-{name}.png"))
        drv.execute_script("document.querySelector('[data-testid=timing-chart]').scrollIntoView()")
        drv.save_screenshot(str(artifacts / f"glance-chart-{name}.png"))
        Select(el(drv, "machine")).select_by_value("soft-plc")
        Select(el(drv, "example")).select_by_value("parts")
        wait(drv, lambda: drv.find_elements(By.CSS_SELECTOR, '[data-kind="box"]'))
        close_menu(drv)
        boxes = drv.find_elements(By.CSS_SELECTOR, '[data-kind="box"]')
        box = max(boxes, key=lambda b: len(b.get_attribute("title") or ""))
        drv.execute_script("arguments[0].scrollIntoView({block: 'center'})", box)
        ActionChains(drv).click(box).perform()
        drv.save_screenshot(str(artifacts / f"glance-box-{name}.png"))
    finally:
        drv.quit()
