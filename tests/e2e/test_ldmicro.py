"""End-to-end: LDmicro `.ld` files open in the page (issue #32): drawn on
the soft PLC, run from its board; a bad file said at its line."""

from selenium.webdriver.common.by import By

from test_app import drawn, el, on, open_fresh, severe_console_messages, wait

# Written for these tests (LDmicro's own files are not committed): a
# counter of Xa's rises to 3 lights Yq, Xr resets it; a 0.1 file at a
# 10 ms cycle, CRLF line ends as LDmicro writes them on Windows.
COUNTER = "\r\n".join([
    "LDmicro0.1",
    "MICRO=Atmel AVR ATmega328 28-PDIP",
    "CYCLE=10000",
    "CRYSTAL=16000000",
    "BAUD=2400",
    "",
    "IO LIST",
    "    Xa at 14",
    "    Xr at 15",
    "    Yq at 16",
    "END",
    "",
    "PROGRAM",
    "RUNG",
    "    COMMENT Count Xa's rises; Yq at 3.",
    "END",
    "RUNG",
    "    CONTACTS Xa 0",
    "    CTU Cparts 3",
    "    COIL Yq 0 0 0",
    "END",
    "RUNG",
    "    CONTACTS Xr 0",
    "    RES Cparts",
    "END",
    "",
])


def test_an_ld_file_opens_on_the_soft_plc_and_runs_from_its_board(driver, base_url, tmp_path, artifacts):
    open_fresh(driver, base_url)
    assert el(driver, "machine").get_attribute("value") != "soft-plc"
    path = tmp_path / "counter.ld"
    path.write_bytes(COUNTER.encode("latin-1"))
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: el(driver, "machine").get_attribute("value") == "soft-plc",
         message="the page switches to the soft PLC")
    wait(driver, lambda: drawn(driver, "var-Cparts"),
         message="the file's names in the variables pane")
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text
    boxes = [b.text for b in driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-kind="box"]')]
    assert any("LD_CTU" in b for b in boxes), boxes
    el(driver, "run").click()
    # The IO LIST's order on the board: Xa, Xr on %IX0.0, %IX0.1.
    label = lambda testid: el(driver, testid).find_element(By.XPATH, "..").text
    wait(driver, lambda: "Xa" in label("soft-input-IX0-0") and "Xr" in label("soft-input-IX0-1"))
    for n in range(3):
        el(driver, "soft-input-IX0-0").click()
        el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="three rises count to 3: Yq")
    el(driver, "soft-input-IX0-1").click()
    wait(driver, lambda: not on(driver, "soft-lamp-QX0-0"), message="Xr resets the count")
    driver.save_screenshot(str(artifacts / "ldmicro-opened.png"))
    # Written back as LDmicro 4.x writes it, and opened again the same.
    from test_ladder import CAPTURE, downloads, saved_ladder
    before = saved_ladder(driver, "soft-plc")
    driver.execute_script(CAPTURE)
    el(driver, "export-ld").click()
    text = downloads(driver, 1)["soft-plc-ladder.ld"]
    assert text.startswith("LDmicro0.2\nCYCLE=10000 us"), text
    for line in ["Xa at 14", "CONTACTS Xa 0 0", "CTU Cparts 3 0 /", "COIL Yq 0 0 0 0", "COMMENT Count Xa's rises; Yq at 3."]:
        assert line in text, (line, text)
    path = tmp_path / "again.ld"
    path.write_text(text)
    el(driver, "new-ladder").click()
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: saved_ladder(driver, "soft-plc") == before, message="the same ladder again")
    assert severe_console_messages(driver) == []


def test_an_ld_file_with_hardware_the_page_does_not_simulate_is_refused_at_its_line(driver, base_url, tmp_path):
    open_fresh(driver, base_url)
    bad = COUNTER.replace("    RES Cparts", "    I2C_WR I2C1 a b c d e f g")
    path = tmp_path / "i2c.ld"
    path.write_text(bad)
    before = el(driver, "machine").get_attribute("value")
    el(driver, "open-file").send_keys(str(path))
    message = wait(driver, lambda: "I2C_WR" in el(driver, "edit-message").text and el(driver, "edit-message"))
    assert message.text.startswith("i2c.ld:24: I2C_WR drives hardware"), message.text
    assert el(driver, "machine").get_attribute("value") == before, "nothing changed"
    assert severe_console_messages(driver) == []


def from_palette(driver, item, opens_with, typed, cell):
    """A palette item clicked: its entry opens with `opens_with`, takes
    `typed` and Enter, and the box lands in `cell`."""
    from selenium.webdriver.common.keys import Keys
    el(driver, f"palette-{item}").click()
    entry = wait(driver, lambda: el(driver, "device-input"))
    assert entry.get_attribute("value") == opens_with
    entry.send_keys(typed, Keys.ENTER)
    wait(driver, lambda: opens_with.strip() in el(driver, cell).text)


def declare_dint(driver, name):
    el(driver, "var-new-name").send_keys(name)
    el(driver, "var-new-type").clear()
    el(driver, "var-new-type").send_keys("DINT")
    el(driver, "var-add").click()
    wait(driver, lambda: drawn(driver, f"var-{name}"))


def test_ldmicros_timer_is_in_the_soft_plcs_palette_and_counts_scans(driver, base_url):
    """LD_TON from the palette: 20 scans of 10 ms counted in Tw, then the
    lamp, as LDmicro's TON does."""
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import Select
    from test_ladder import focus_ladder, place
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("soft-plc")
    wait(driver, lambda: el(driver, "soft-board"))
    focus_ladder(driver)
    place(driver, Keys.F5, "%IX0.0")
    from_palette(driver, "ld-ton", "LD_TON ", "Tw_ld 20 Tw", "cell-0-0-1")
    # Its count is a word: declared, as every word is.
    declare_dint(driver, "Tw")
    focus_ladder(driver, "cell-0-0-2")
    place(driver, Keys.F7, "%QX0.0")
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text
    el(driver, "run").click()
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="on after 20 scans")
    assert "Tw=20" in el(driver, "cell-0-0-1").text, el(driver, "cell-0-0-1").text
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: not on(driver, "soft-lamp-QX0-0"))
    assert severe_console_messages(driver) == []


# Written for this test: greets with a formatted string showing a
# count, then echoes each key while the transmitter is free.
ECHO = "\n".join([
    "LDmicro0.2",
    "CYCLE=10000",
    "PROGRAM",
    "RUNG",
    "    CONTACTS Rsaid 1",
    "    MOVE count 42",
    "    FORMATTED_STRING count 10 72 105 44 32 92 51 92 114 92 110",
    "    COIL Rsaid 0 1 0",
    "END",
    "RUNG",
    "    UART_SEND_READY",
    "    UART_RECV ch",
    "    COIL Rgot 0 0 0",
    "END",
    "RUNG",
    "    CONTACTS Rgot 0",
    "    UART_SEND ch",
    "END",
    "",
])


def test_an_ld_files_uart_talks_through_the_serial_monitor(driver, base_url, tmp_path, artifacts):
    open_fresh(driver, base_url)
    assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="soft-monitor"]')
    path = tmp_path / "echo.ld"
    path.write_text(ECHO)
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: drawn(driver, "var-count"))
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text
    el(driver, "run").click()
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="soft-monitor"]'),
         message="a program using the UART gets a serial monitor")
    monitor = lambda: el(driver, "soft-monitor").text
    wait(driver, lambda: monitor().startswith("Hi,  42"), message="the formatted string: " + monitor())
    line = el(driver, "soft-monitor-input")
    line.send_keys("abc\n")
    wait(driver, lambda: monitor().endswith("abc"), message="echoed: " + repr(monitor()))
    line.send_keys("\n")
    line.send_keys("z\n")
    wait(driver, lambda: monitor().endswith("abc\nz"), message="Enter alone is a CR: " + repr(monitor()))
    driver.save_screenshot(str(artifacts / "ldmicro-serial.png"))
    # A key that is no byte is refused in the monitor, nothing typed.
    line.send_keys("\u00e9\u3042\n")
    wait(driver, lambda: "not a byte" in monitor(), message=monitor())
    assert severe_console_messages(driver) == []


def test_an_ld_files_cycle_becomes_the_soft_plcs_scan(driver, base_url, tmp_path):
    # A 0.1 file at a 5 ms cycle: TON 50 ms is 9 cycles (LDmicro 2.x's
    # adjust), so Yq comes on after 10 scans, 50 ms, at the file's pace.
    open_fresh(driver, base_url)
    path = tmp_path / "fast.ld"
    path.write_text("LDmicro0.1\nCYCLE=5000\nPROGRAM\nRUNG\n  CONTACTS Xa 0\n  TON Tw 50000\n  COIL Yq 0 0 0\nEND\n")
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: el(driver, "soft-scan").get_attribute("value") == "5",
         message="the scan period follows the file's CYCLE")
    assert "scans every 5 ms" in driver.find_element(By.TAG_NAME, "body").text
    # Written back at that cycle.
    from test_ladder import CAPTURE, downloads
    driver.execute_script(CAPTURE)
    el(driver, "export-ld").click()
    assert "CYCLE=5000 us" in downloads(driver, 1)["soft-plc-ladder.ld"]
    # A period the machine refuses is said beside the field, which keeps
    # what the machine runs at.
    from selenium.webdriver.common.keys import Keys
    field = el(driver, "soft-scan")
    field.send_keys(Keys.CONTROL, "a")
    field.send_keys("0\n")
    said = lambda: field.find_element(By.XPATH, "..").find_element(By.CSS_SELECTOR, ".soft-refused").text
    wait(driver, lambda: "scan" in said(), message="refused: " + said())
    wait(driver, lambda: el(driver, "soft-scan").get_attribute("value") == "5")
    # It stays over a reload.
    driver.refresh()
    from selenium.webdriver.support.ui import Select
    wait(driver, lambda: el(driver, "mode-run"), message="the page again")
    Select(el(driver, "machine")).select_by_value("soft-plc")
    wait(driver, lambda: el(driver, "soft-scan").get_attribute("value") == "5")
    assert severe_console_messages(driver) == []


def test_the_serial_count_example_talks_in_the_monitor(driver, base_url):
    from selenium.webdriver.support.ui import Select
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("soft-plc")
    wait(driver, lambda: el(driver, "soft-board"))
    Select(el(driver, "example")).select_by_value("serial-count")
    wait(driver, lambda: drawn(driver, "var-count"))
    el(driver, "run").click()
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="soft-monitor"]'))
    switch = el(driver, "soft-input-IX0-0")
    switch.click()
    switch.click()
    monitor = lambda: el(driver, "soft-monitor").text
    wait(driver, lambda: "count =      1" in monitor(), message=monitor())
    el(driver, "soft-monitor-input").send_keys("r\n")
    switch.click()
    wait(driver, lambda: monitor().count("count =      1") == 2, message="counted again from 0: " + monitor())
    assert severe_console_messages(driver) == []


# Written for these tests: each rise of Xa adds one to n, shown on a
# common-cathode digit `seg` and a common-anode digit `an`, and on a
# 14- and a 16-segment digit.
DIGITS = "\n".join([
    "LDmicro0.2",
    "CYCLE=10000",
    "",
    "VAR LIST",
    "    1 bytes seg",
    "    1 bytes an",
    "    2 bytes w14",
    "    4 bytes w16",
    "END",
    "",
    "IO LIST",
    "    Xa at 14",
    "END",
    "",
    "PROGRAM",
    "RUNG",
    "    CONTACTS Xa 0",
    "    OSR",
    "    ADD n n 1",
    "END",
    "RUNG",
    "    PARALLEL",
    "        7SEGMENTS seg n C",
    "        7SEGMENTS an n A",
    "        14SEGMENTS w14 n C",
    "        16SEGMENTS w16 n C",
    "    END",
    "END",
    "",
])


def lit_segments(driver, testid):
    """The segments drawn lit in a digit, as letters (`.` the point;
    engine's `segments::names`)."""
    return driver.execute_script(
        "const d = document.querySelector(arguments[0]);"
        "return [...d.querySelectorAll('svg .seg')].map(s => s.classList.contains('lit') ? s.dataset.seg : '').join('');",
        f'[data-testid="{testid}"]')


def open_ld(driver, tmp_path, file_name, text, variable):
    """Opens `text` as the .ld file `file_name`, until `variable` is in
    the variables pane."""
    path = tmp_path / file_name
    path.write_text(text)
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: drawn(driver, f"var-{variable}"),
         message="the file's names in the variables pane")


def open_digits(driver, tmp_path):
    """Opens DIGITS and runs it: a digit on the board for each 7SEGMENTS."""
    open_ld(driver, tmp_path, "digits.ld", DIGITS, "seg")
    el(driver, "run").click()
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="soft-digit-seg"]'),
         message="a digit on the board for each 7SEGMENTS")


def test_an_ld_files_7_segment_digits_are_drawn_on_the_board(driver, base_url, tmp_path, artifacts):
    open_fresh(driver, base_url)
    open_digits(driver, tmp_path)
    assert el(driver, "soft-digit-an").get_attribute("data-common") == "A"
    wait(driver, lambda: el(driver, "soft-digit-seg").get_attribute("data-lit") == "abcdef", message="0")
    for _ in range(3):
        el(driver, "soft-input-IX0-0").click()
        el(driver, "soft-input-IX0-0").click()
    # 3: a, b, c, d and g, on the anode digit too (its bits inverted).
    wait(driver, lambda: el(driver, "soft-digit-seg").get_attribute("data-lit") == "abcdg", message="3")
    assert lit_segments(driver, "soft-digit-seg") == "abcdg"
    assert lit_segments(driver, "soft-digit-an") == "abcdg"
    assert el(driver, "soft-digit-an").get_attribute("data-lit") == "abcdg"
    # 3 on 14 segments: the middle's right half; on 16, a and d whole.
    assert lit_segments(driver, "soft-digit-w14") == "abcdG"
    assert lit_segments(driver, "soft-digit-w16") == "abcdGDA"
    driver.save_screenshot(str(artifacts / "ldmicro-digits.png"))
    assert severe_console_messages(driver) == []


def test_a_digit_from_the_palette_is_drawn_on_the_board(driver, base_url):
    """LD_SEG7 from the palette on a rung of its own: 5 on the board's
    digit; the formatted string's item puts its call form in the entry."""
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import Select
    from test_ladder import focus_ladder, place
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("soft-plc")
    wait(driver, lambda: el(driver, "soft-board"))
    focus_ladder(driver)
    from_palette(driver, "ld-seg7", "LD_SEG7 ", "seg_ld 5 0 seg 8", "cell-0-0-0")
    declare_dint(driver, "seg")
    focus_ladder(driver, "cell-0-0-1")
    place(driver, Keys.F7, "%QX0.0")
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text
    el(driver, "run").click()
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="soft-digit-seg"]'))
    wait(driver, lambda: lit_segments(driver, "soft-digit-seg") == "acdfg", message="5")
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="the power passes the digit's box")
    focus_ladder(driver, "cell-0-1-0")
    el(driver, "palette-ld-fmtstr").click()
    entry = wait(driver, lambda: el(driver, "device-input"))
    assert entry.get_attribute("value").startswith("fmt_ld: LD_FMTSTR(V := n, FMT := '")
    assert severe_console_messages(driver) == []


# Written for this test: while Xa is on, STRING prints the count of
# scans into `msg` as "n=%04d" (codes 110 61 37 48 52 100).
STRINGS = "\n".join([
    "LDmicro0.2",
    "CYCLE=10000",
    "IO LIST",
    "    Xa at 1",
    "END",
    "PROGRAM",
    "RUNG",
    "    ADD n n 1",
    "END",
    "RUNG",
    "    CONTACTS Xa 0",
    "    STRING msg n 6 110 61 37 48 52 100",
    "END",
    "",
])


def var_value(driver, name):
    """The value the variables pane shows for `name` (all of it, where a
    long text is cut on screen)."""
    return driver.find_element(By.CSS_SELECTOR, f'[data-testid="var-{name}"] [data-testid="var-value"]').get_attribute("textContent")


def test_an_ld_files_string_prints_into_a_string_variable(driver, base_url, tmp_path, artifacts):
    """STRING prints the count into `msg`, a STRING the variables pane
    shows in quotes, and keeps it while its rung is off."""
    import re
    open_fresh(driver, base_url)
    open_ld(driver, tmp_path, "strings.ld", STRINGS, "msg")
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text
    row = el(driver, "var-msg")
    assert row.find_element(By.CSS_SELECTOR, '[data-testid="var-type"]').get_attribute("value") == "STRING"
    el(driver, "run").click()
    wait(driver, lambda: var_value(driver, "msg") == "''", message="nothing printed while Xa is off")
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: re.fullmatch(r"'n=\d{4}'", var_value(driver, "msg")),
         message="the count printed with four digits")
    el(driver, "soft-input-IX0-0").click()
    kept = var_value(driver, "msg")
    count = int(var_value(driver, "n"))
    wait(driver, lambda: int(var_value(driver, "n")) > count + 5, message="the scans go on")
    assert var_value(driver, "msg") == kept, "kept while Xa is off"
    driver.save_screenshot(str(artifacts / "ldmicro-string.png"))
    assert severe_console_messages(driver) == []


def test_ldmicros_string_is_in_the_soft_plcs_palette(driver, base_url):
    from selenium.webdriver.support.ui import Select
    from test_ladder import focus_ladder
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("soft-plc")
    wait(driver, lambda: el(driver, "soft-board"))
    focus_ladder(driver)
    el(driver, "palette-ld-string").click()
    entry = wait(driver, lambda: el(driver, "device-input"))
    assert entry.get_attribute("value") == "str_ld: LD_STRING(V := n, D := msg, FMT := 'n=%d', D => msg)"
    assert severe_console_messages(driver) == []
