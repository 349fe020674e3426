"""End-to-end: the parts of the page fetched on first use (issue #53,
docs/performance.md "Parts"). A part that cannot be fetched says so where
it was asked for and offers to retry, with the user's work untouched; a
part never opened online opens offline after the first visit (the
service worker keeps every part)."""

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from test_app import drawn, el, on, open_fresh, wait
from test_ladder import first_visit_kept_offline, focus_ladder, place


def block(driver, patterns):
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.setBlockedURLs", {"urls": patterns})


def test_a_part_that_cannot_be_fetched_says_so_and_offers_to_retry(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    listing = el(driver, "il-listing").text
    block(driver, ["*split_cpu_view*"])
    try:
        el(driver, "cpu-view-open").click()
        wait(driver, lambda: el(driver, "cpu-part-missing", reveal=False), message="the CPU view says it is missing")
        assert "could not be fetched" in el(driver, "cpu-part-missing").text
        # Nothing else changed: the ladder is as it was.
        assert "ST   Y00" in listing
        assert el(driver, "il-listing").text == listing
    finally:
        block(driver, [])
    el(driver, "cpu-part-retry").click()
    wait(driver, lambda: el(driver, "cpu-view").is_displayed(), message="the retry fetches the part")


def test_a_part_never_opened_online_opens_offline(driver):
    server = first_visit_kept_offline(driver)
    url = server.url
    server.stop()
    driver.get(url)
    wait(driver, lambda: el(driver, "ladder"), message="the page loads with the server gone")
    el(driver, "cpu-view-open").click()
    wait(driver, lambda: el(driver, "cpu-view").is_displayed(), message="the CPU view opens offline")


def test_running_the_tests_when_their_part_cannot_be_fetched_says_so(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    el(driver, "tests-open").click()
    wait(driver, lambda: el(driver, "add-test")).click()
    case = wait(driver, lambda: el(driver, "test-case-0"))
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-events"]').send_keys("0.1s,X00,1\n")
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]').send_keys("Y00 = 1 at 0.2s")
    block(driver, ["*split_tests_runner*"])
    try:
        el(driver, "run-tests").click()
        wait(driver, lambda: "could not be fetched" in el(driver, "edit-message", reveal=False).text,
             message="the message line says the runner is missing")
        assert el(driver, "test-case-0").get_attribute("data-result") in (None, "")
    finally:
        block(driver, [])
    # Run again is the retry; the case the user wrote is still there.
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "pass")


def test_a_machine_whose_part_cannot_be_fetched_keeps_its_ladder_and_retries(driver, base_url):
    """Each machine but the first screen's arrives with its part: the
    soft PLC's blocked, its ladder is still drawn and edited, its panel
    says the part is missing, and Run pressed meanwhile runs once the
    retry has brought it."""
    from selenium.webdriver.support.ui import Select
    open_fresh(driver, base_url)
    block(driver, ["*split_soft_plc*"])
    try:
        Select(el(driver, "machine")).select_by_value("soft-plc")
        wait(driver, lambda: el(driver, "machine-panel-missing", reveal=False),
             message="the panel says the soft PLC could not be fetched")
        assert "could not be fetched" in el(driver, "machine-panel-missing").text
        focus_ladder(driver)
        place(driver, Keys.F5, "%IX0.0")
        place(driver, Keys.F7, "%QX0.0")
        el(driver, "run").click()
    finally:
        block(driver, [])
    el(driver, "machine-panel-retry").click()
    wait(driver, lambda: el(driver, "soft-board"), message="the retry brings the soft PLC")
    # The ladder drawn meanwhile compiles and runs on it (Run waited).
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="the lamp follows the input")


def test_every_machine_plant_and_format_works_offline_after_one_visit(driver, tmp_path):
    """Issue #53: after one visit every machine, plant and file format
    works with the server gone, though that visit opened none of them."""
    from selenium.webdriver.support.ui import Select
    from test_ldmicro import COUNTER
    from test_plant import choose, figures
    server = first_visit_kept_offline(driver)
    url = server.url
    server.stop()
    driver.get(url)
    wait(driver, lambda: el(driver, "ladder"), message="the page loads with the server gone")
    for machine, board in [("io86a", "io86a-terminal"), ("avr-plc", "avr-program-text"),
                           ("arduino-plc", "arduino-monitor"), ("soft-plc", "soft-board")]:
        Select(el(driver, "machine")).select_by_value(machine)
        wait(driver, lambda: el(driver, board), message=f"{machine} opens offline")
    # A file format (LDmicro's, read by the files worker) and a plant.
    path = tmp_path / "counter.ld"
    path.write_bytes(COUNTER.encode("latin-1"))
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: drawn(driver, "var-Cparts"), message="an LDmicro file opens offline")
    choose(driver, "tank")
    wait(driver, lambda: figures(driver), message="a plant is drawn offline")


def test_a_share_link_made_while_its_codec_cannot_be_fetched_says_so(driver, base_url):
    """The share links' codec is a part: Share says where it was pressed
    that it could not be fetched, and pressing it again makes the link."""
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    block(driver, ["*split_share_codec*"])
    try:
        el(driver, "share").click()
        wait(driver, lambda: "could not be fetched" in el(driver, "edit-message", reveal=False).text,
             message="the message line says the codec is missing")
        assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="share-url"]')
    finally:
        block(driver, [])
    el(driver, "share").click()
    link = wait(driver, lambda: el(driver, "share-url").get_attribute("value"))
    assert "#" in link
    # The link opens the ladder in a fresh profile (the codec fetched there too).
    open_fresh(driver, base_url)
    driver.get(link)
    wait(driver, lambda: el(driver, "shared-banner"), message="the shared ladder is shown")


def test_a_tools_pane_is_fetched_when_its_tab_is_first_shown(driver, base_url):
    """The tools' panes the first screen does not show (the chart, Tests,
    Why?, the listing, Find, Projects, the import dialog) are parts: the
    first screen fetches none; the chart's tab, its part blocked, says so
    in the pane and retries, with the ladder untouched."""
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    fetched = driver.execute_script(
        "return performance.getEntriesByType('resource').map(e => e.name).filter(n => n.includes('split_pane_'))")
    assert fetched == [], f"the first screen fetched panes: {fetched}"
    assert driver.find_elements(By.CSS_SELECTOR, '[data-lazy-pane="chart"]'), "the chart is not drawn before its tab"
    block(driver, ["*split_pane_chart*"])
    try:
        driver.find_element(By.CSS_SELECTOR, '[data-testid="dock-tab-chart"]').click()
        wait(driver, lambda: el(driver, "chart-part-missing", reveal=False), message="the chart's tab says it is missing")
        assert "could not be fetched" in el(driver, "chart-part-missing", reveal=False).text
    finally:
        block(driver, [])
    el(driver, "chart-part-retry").click()
    wait(driver, lambda: el(driver, "timing-chart").is_displayed(), message="the retry draws the chart")
    assert "ST   Y00" in el(driver, "il-listing").text
