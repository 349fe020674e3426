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


def import_dialog(driver, base_url, path, why, machine="io86a"):
    """A fresh page on `machine` with `path` opened: its import dialog
    (`why` it is shown)."""
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value(machine)
    wait(driver, lambda: el(driver, "palette"))
    el(driver, "open-file").send_keys(str(path))
    return wait(driver, lambda: el(driver, "import-dialog"), message=why)


def test_a_project_with_named_variables_imports_through_the_mapping_table(driver, base_url):
    import_dialog(driver, base_url, NAMED, "the dialog, since memo has no device")
    memo = el(driver, "import-map-memo")
    assert memo.get_attribute("value") == "Y01", "a free output proposed for what a coil writes"
    # A device the machine lacks: refused at its row of the table (the map's
    # place, issue #24), nothing changed.
    before = devices(driver)
    memo.clear()
    memo.send_keys("Q9")
    el(driver, "import-apply").click()
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-error"]'))
    error = el(driver, "import-error").text
    assert error.startswith("memo → Q9: unknown device"), error
    assert devices(driver) == before
    memo.clear()
    memo.send_keys("M05")
    el(driver, "import-apply").click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]'))
    got = devices(driver)
    for d in ["X00", "X01", "M02", "Y00", "M05"]:
        assert d in got, (d, got)
    # The app bar names the file opened.
    assert el(driver, "app-project").text == NAMED.name
    # One undo away from the ladder before.
    el(driver, "undo").click()
    wait(driver, lambda: devices(driver) == before)
    # New ladder: untitled again.
    el(driver, "new-ladder").click()
    wait(driver, lambda: el(driver, "app-project").text == "Untitled")


FBD = ROOT / "engine/tests/ladder/fixtures/openplc-fbd.xml"


def test_an_fbd_program_imports_as_the_ladder_its_blocks_say(driver, base_url):
    import_dialog(driver, base_url, FBD, "the dialog, since lamp has no device")
    assert el(driver, "import-map-lamp").get_attribute("value") == "Y00"
    el(driver, "import-apply").click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]'))
    # lamp = start AND NOT stop (the negated box is X01's NC contact); alarm = stop.
    assert {"X00", "X01", "Y00", "Y01"} <= devices(driver)
    nc = driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-device="X01"][data-kind="nc"]')
    assert len(nc) == 1, "X01 read negated once, plainly once"
    listing = el(driver, "il-listing").text
    assert "ANI X01" in listing and "OUT Y01" in listing, listing


def test_the_avr_plc_imports_with_its_bits_laid_out_as_its_seed_does(driver, base_url):
    """Located inputs are R4, outputs R5; the dialog proposes the next
    free output for what a coil writes."""
    import_dialog(driver, base_url, FBD, "the dialog, since lamp has no device", "avr-plc")
    assert el(driver, "import-map-lamp").get_attribute("value") == "R5.0"
    el(driver, "import-apply").click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]'))
    assert {"R4.0", "R4.1", "R5.0", "R5.1"} <= devices(driver)
    listing = el(driver, "il-listing").text
    assert "And_B,4,Bit1,0" in listing and "Coil_A,5,Bit0,0" in listing, listing
