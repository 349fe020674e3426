"""End-to-end: accessibility (issue #27). axe-core (from the npm registry,
installed into .tools/ by scripts/setup.sh) checks each machine's
workspace against WCAG 2.1 A/AA, with a test case, each pane and each
dock tab open (issue #46): no critical or serious finding."""

import pathlib

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

from test_app import ROOT, el, open_fresh, wait
from test_glance import close_menu

AXE = ROOT / ".tools" / "node_modules" / "axe-core" / "axe.min.js"
MACHINES = ["minasec-u", "io86a", "arduino-plc", "avr-plc", "soft-plc"]
PANES = [None, "tests-open", "projects-open", "find-open", "keys"]


def violations(driver):
    """axe-core's critical and serious findings on the page as it is."""
    driver.execute_script(pathlib.Path(AXE).read_text())
    driver.set_script_timeout(60)
    found = driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "axe.run(document, {runOnly: {type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']}})"
        ".then(r => done(r.violations.map(v => ({id: v.id, impact: v.impact,"
        "  nodes: v.nodes.slice(0, 4).map(n => n.target.join(' '))}))))"
        ".catch(e => done([{id: 'axe-error', impact: 'critical', nodes: [String(e)]}]));")
    return [v for v in found if v["impact"] in ("critical", "serious")]


@pytest.mark.parametrize("machine", MACHINES)
def test_no_critical_or_serious_finding_on_any_workspace(driver, base_url, machine):
    assert AXE.exists(), "run scripts/setup.sh (it installs axe-core)"
    driver.set_window_size(1366, 768)
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value(machine)
    wait(driver, lambda: el(driver, "palette"))
    if machine == "soft-plc":
        # Its variables pane with rows, and boxes on the ladder.
        Select(el(driver, "example")).select_by_value("parts")
        wait(driver, lambda: el(driver, "var-parts"))
        close_menu(driver)
    if machine == "minasec-u":
        # The view inside its CPU, an edge stepped (blocks lit).
        el(driver, "mode-halt").click()
        el(driver, "cpu-view-open").click()
        # The diagram is a part fetched at the first opening (issue #53).
        wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="cpu-step-edge"]'))
        el(driver, "cpu-step-edge").click()
        wait(driver, lambda: el(driver, "cpu-phase").get_attribute("data-value") == "rising")
    # A case in the Tests pane, so its fields are checked too.
    el(driver, "tests-open").click()
    el(driver, "add-test").click()
    wait(driver, lambda: el(driver, "test-case-0"))
    el(driver, "tests-open").click()
    found = {}
    for pane in PANES:
        if pane:
            el(driver, pane).click()
        for v in violations(driver):
            found.setdefault(v["id"], (v["impact"], pane, v["nodes"]))
        if pane:
            el(driver, pane).click()  # closed again before the next opens
    # Each dock tab open in turn (issue #46): every tool's view checked.
    # (The panel's own tab shows only where the docks are sheets.)
    tabs = [t.get_attribute("data-testid") for t in
            driver.find_elements(By.CSS_SELECTOR, '[data-testid^="dock-tab-"]')
            if t.get_attribute("data-testid") != "dock-tab-panel"]
    assert "dock-tab-chart" in tabs, tabs
    for tab in tabs:
        if el(driver, "dock-bottom").get_attribute("data-open") == "false":
            el(driver, "view-tools-dock").click()
            wait(driver, lambda: el(driver, "dock-bottom").get_attribute("data-open") == "true")
        el(driver, tab).click()
        wait(driver, lambda: el(driver, tab).get_attribute("aria-selected") == "true", message=tab)
        for v in violations(driver):
            found.setdefault(v["id"], (v["impact"], tab, v["nodes"]))
    assert not found, found


def test_skip_links_reach_the_ladder_and_the_panel_without_touching_the_address(driver, base_url):
    from selenium.webdriver.common.keys import Keys
    open_fresh(driver, base_url)
    body = driver.find_element("css selector", "body")
    body.send_keys(Keys.TAB)
    first = driver.switch_to.active_element
    assert first.get_attribute("href").endswith("#ladder"), "the first Tab stop"
    first.send_keys(Keys.ENTER)
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "ladder")
    driver.execute_script("document.querySelectorAll('a.skip')[1].focus()")
    driver.switch_to.active_element.send_keys(Keys.ENTER)
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("id") == "panel")
    assert driver.execute_script("return location.hash") == "", "a share link's place is left alone"
    assert not driver.find_elements("css selector", '[data-testid="notice"]')


def test_japanese_mode_names_cells_palette_and_lamps_in_japanese(driver, base_url):
    open_fresh(driver, base_url, lang="ja")
    assert el(driver, "cell-0-0-0").get_attribute("aria-label") == "ラダーの終わり、列 1"
    Select(el(driver, "example")).select_by_value("seed-test")
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-device") == "X00")
    label = el(driver, "cell-0-0-0").get_attribute("aria-label")
    assert label.startswith("回路1 1行 1列: a接点 X00"), label
    assert el(driver, "palette-no").get_attribute("title").startswith("a接点")
    assert "データ命令がありません" in el(driver, "palette-mov").get_attribute("title")
    assert el(driver, "lamp-Y00").get_attribute("aria-label").endswith("消灯")
    assert el(driver, "break-input").get_attribute("placeholder").startswith("例")


def test_the_soft_plcs_7_segment_digits_pass_axe(driver, base_url, tmp_path):
    """An LDmicro file's digits on the soft PLC's board (issue #32)."""
    from test_ldmicro import open_digits
    driver.set_window_size(1366, 768)
    open_fresh(driver, base_url)
    open_digits(driver, tmp_path)
    assert violations(driver) == []
