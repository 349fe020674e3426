"""End-to-end: the run model (issue #28): what the ladder shows is what
the machine runs. While it runs the drawing, an import is written to it at
once; a drawing with problems shows no live state and says why."""

import time

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import el, on, open_fresh, severe_console_messages, wait
from test_ladder import focus_ladder, place

# A blinker: T00 times while T01 is off, T01 while T00 is on; `lamp`
# (declared with no address, so the import dialog asks) shows T00.
BLINK = """<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="blink" pouType="program">
<interface><localVars><variable name="lamp"><type><BOOL/></type></variable></localVars></interface>
<body><LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>
<contact localId="2" negated="true"><position x="10" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>T01</variable></contact>
<inVariable localId="3"><position x="20" y="20"/><connectionPointOut/><expression>T#300ms</expression></inVariable>
<block localId="4" typeName="TON" instanceName="T00"><position x="30" y="0"/><inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable><variable formalParameter="PT"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable></inputVariables><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables></block>
<coil localId="5"><position x="60" y="0"/><connectionPointIn><connection refLocalId="4" formalParameter="Q"/></connectionPointIn><variable>lamp</variable></coil>
<contact localId="6"><position x="10" y="40"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>T00</variable></contact>
<inVariable localId="7"><position x="20" y="60"/><connectionPointOut/><expression>T#300ms</expression></inVariable>
<block localId="8" typeName="TON" instanceName="T01"><position x="30" y="40"/><inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="6"/></connectionPointIn></variable><variable formalParameter="PT"><connectionPointIn><connection refLocalId="7"/></connectionPointIn></variable></inputVariables><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables></block>
</LD></body></pou></pous></types></project>
"""


SAMPLE = """
const lamp = document.querySelector('[data-testid="io86a-lamp-Y00"]').getAttribute('data-on');
const coils = [...document.querySelectorAll('[data-testid="ladder"] [data-device="Y00"]')]
  .map(c => c.getAttribute('data-on'));
return [lamp, coils];
"""


def y00_cells(driver):
    return driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-device="Y00"]')


def io86a_x00_to_y00_drawn(driver, base_url):
    """X00 → Y00 drawn by keys on PLC-IO86A, not yet written."""
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("io86a")
    wait(driver, lambda: el(driver, "palette"))
    # The workspace opens on its example; this starts from nothing.
    el(driver, "new-ladder").click()
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")


def io86a_running_x00_to_y00(driver, base_url):
    """X00 → Y00 drawn by keys on PLC-IO86A, running, X00 on."""
    io86a_x00_to_y00_drawn(driver, base_url)
    el(driver, "run").click()
    el(driver, "io86a-input-X00").click()
    wait(driver, lambda: on(driver, "io86a-lamp-Y00"), message="X00 lights Y00")
    for _ in range(10):
        assert on(driver, "io86a-lamp-Y00"), "held on by X00"
        time.sleep(0.05)


def test_an_import_while_running_is_what_runs(driver, base_url, tmp_path):
    io86a_running_x00_to_y00(driver, base_url)
    path = tmp_path / "blink.xml"
    path.write_text(BLINK)
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: el(driver, "import-dialog"), message="lamp needs a device")
    lamp = el(driver, "import-map-lamp")
    lamp.clear()
    lamp.send_keys("Y00")
    el(driver, "import-apply").click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]'))
    wait(driver, lambda: any(c.get_attribute("data-device") == "Y00" for c in y00_cells(driver)))
    # From now on the lamp and the drawn coil blink together: both read
    # in one script, between two frames.
    seen = set()
    for _ in range(60):
        lamp_on, coils = driver.execute_script(SAMPLE)
        seen.add(lamp_on)
        assert coils and set(coils) == {lamp_on}, (lamp_on, coils)
        time.sleep(0.05)
    # X00 → Y00 held it on: blinking, it is the imported program that runs.
    assert seen == {"1", "0"}, "the lamp blinks: the imported program runs"
    assert el(driver, "not-written").get_attribute("hidden") is not None
    assert severe_console_messages(driver) == []


def test_a_drawing_with_problems_shows_no_live_state_and_says_why(driver, base_url):
    io86a_running_x00_to_y00(driver, base_url)
    assert el(driver, "cell-0-0-0").get_attribute("data-on") == "1"
    # A contact on the free row, joined to nothing: a problem.
    el(driver, "cell-0-1-2").click()
    place(driver, Keys.F5, "X01")
    wait(driver, lambda: el(driver, "not-written").get_attribute("hidden") is None,
         message="said why nothing live is shown")
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-on") != "1",
         message="no live state")
    assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-powered="1"]')
    # Undone: written again at once, live again.
    el(driver, "undo").click()
    wait(driver, lambda: el(driver, "not-written").get_attribute("hidden") is not None)
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-on") == "1",
         message="live again")


def test_run_becomes_stop_and_stop_stops_the_machine(driver, base_url):
    io86a_running_x00_to_y00(driver, base_url)
    run = el(driver, "run")
    wait(driver, lambda: run.get_attribute("aria-pressed") == "true", message="running the drawing")
    assert "Stop" in run.text
    run.click()
    wait(driver, lambda: run.get_attribute("aria-pressed") == "false")
    assert "Run" in run.text
    # IO86A stops as its STOP does: the scan count stands still.
    at = el(driver, "travel-at").get_attribute("data-mark")
    time.sleep(0.5)
    assert el(driver, "travel-at").get_attribute("data-mark") == at, "no scan runs while stopped"
    # Run again: written and started.
    run.click()
    wait(driver, lambda: run.get_attribute("aria-pressed") == "true", message="running again")
    wait(driver, lambda: el(driver, "travel-at").get_attribute("data-mark") != at, message="scans again")


# How often the clock's first line and its data-ms change over arguments[0] ms.
CLOCK_CHANGES = """
const done = arguments[arguments.length - 1], clock = document.querySelector('[data-testid=sim-time]');
const line = clock.querySelector('.clock-line');
let said = 0, marked = 0, text = line.textContent;
const seen = new MutationObserver(() => {
  if (line.textContent !== text) { said++; text = line.textContent; }
});
seen.observe(line, {subtree: true, characterData: true, childList: true});
const ms = new MutationObserver(() => marked++);
ms.observe(clock, {attributes: true, attributeFilter: ['data-ms']});
setTimeout(() => { seen.disconnect(); ms.disconnect(); done([said, marked]); }, arguments[0]);
"""


def test_the_header_clock_says_running_paused_or_stopped(driver, base_url):
    open_fresh(driver, base_url)
    clock = el(driver, "sim-time")
    # A fresh MINASEC-U stands at HALT: stopped, no scan counted.
    wait(driver, lambda: clock.get_attribute("data-state") == "stopped")
    assert clock.text.startswith("Stopped") and clock.text.split()[-2:] == ["0", "scans"]
    el(driver, "run").click()
    wait(driver, lambda: clock.get_attribute("data-state") == "running")
    # Running, the figures are said four times a second (faster is a blur,
    # and each change lays the app bar out); data-ms follows every frame.
    said, marked = driver.execute_async_script(CLOCK_CHANGES, 2000)
    assert 5 <= said <= 10 and marked > 60, (said, marked)
    el(driver, "pause").click()
    wait(driver, lambda: clock.get_attribute("data-state") == "paused")
    assert clock.text.startswith("Paused")
    # Paused: said at once, the very time the machine stands at.
    ms = int(clock.get_attribute("data-ms"))
    wait(driver, lambda: f"{ms // 1000}.{ms % 1000:03} s" in clock.text, message=clock.text)
    el(driver, "pause").click()
    wait(driver, lambda: clock.get_attribute("data-state") == "running")
    # Stop puts MINASEC-U's switch at HALT.
    wait(driver, lambda: el(driver, "run").get_attribute("aria-pressed") == "true")
    el(driver, "run").click()
    wait(driver, lambda: clock.get_attribute("data-state") == "stopped")
    assert clock.text.startswith("Stopped")
    assert el(driver, "mode-halt").get_attribute("aria-pressed") == "true", "the panel's switch"


def test_write_to_plc_is_run_and_says_so(driver, base_url):
    io86a_x00_to_y00_drawn(driver, base_url)
    el(driver, "ladder-write").click()
    wait(driver, lambda: "Written to the PLC" in el(driver, "edit-message").text)
    wait(driver, lambda: el(driver, "run").get_attribute("aria-pressed") == "true",
         message="running the drawing, as Run does")
    el(driver, "io86a-input-X00").click()
    wait(driver, lambda: on(driver, "io86a-lamp-Y00"), message="the written drawing runs")
