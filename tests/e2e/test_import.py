"""End-to-end: another tool's PLCopen project through the import dialog
(issue #18): proposed devices, edited, refused with the file's line,
imported one undo away."""

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

from test_app import ROOT, el, open_fresh, wait

NAMED = ROOT / "engine/tests/ladder/fixtures/openplc-named.xml"


def devices(driver):
    cells = driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-device]')
    return {c.get_attribute("data-device") for c in cells}


def test_a_project_with_named_variables_imports_through_the_mapping_table(driver, base_url):
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("io86a")
    wait(driver, lambda: el(driver, "palette"))
    el(driver, "open-file").send_keys(str(NAMED))
    wait(driver, lambda: el(driver, "import-dialog"), message="the dialog, since memo has no device")
    memo = el(driver, "import-map-memo")
    assert memo.get_attribute("value") == "Y01", "a free output proposed for what a coil writes"
    # A device the machine lacks: refused at the file's line, nothing changed.
    before = devices(driver)
    memo.clear()
    memo.send_keys("Q9")
    el(driver, "import-apply").click()
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-error"]'))
    error = el(driver, "import-error").text
    assert "openplc-named.xml:" in error and "Q9" in error, error
    assert devices(driver) == before
    memo.clear()
    memo.send_keys("M05")
    el(driver, "import-apply").click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]'))
    got = devices(driver)
    for d in ["X00", "X01", "M02", "Y00", "M05"]:
        assert d in got, (d, got)
    # One undo away from the ladder before.
    el(driver, "undo").click()
    wait(driver, lambda: devices(driver) == before)
