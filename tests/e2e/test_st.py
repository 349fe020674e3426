"""End-to-end: Structured Text in the soft PLC's workspace (issue #55): a
`.st` file opened and run with each line's values beside it, an error at
its line as the user types, a breakpoint that pauses the scan before its
line and Step statement moving the marked line; the editor on a laptop
and a phone, axe clean."""

import time

from selenium.common.exceptions import StaleElementReferenceException
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from test_access import violations
from test_app import ROOT, el, on, open_fresh, severe_console_messages, wait
from test_glance import close_menu
from test_ladder import focus_ladder, place
from test_screens import screen_driver
from test_soft import box_values, choose_soft

PROGRAM = """PROGRAM counter
VAR
  count : INT;
  lamp : BOOL;
  total : INT;
END_VAR
count := count + 1; (* one more each scan *)
lamp := count > 5;
total := total + count;
END_PROGRAM
"""


LIBRARY = """FUNCTION_BLOCK Scale
VAR_INPUT
  go : BOOL;
  x : INT;
END_VAR
VAR_OUTPUT
  ok : BOOL;
  y : INT;
END_VAR
y := x * 2 + 1;
ok := go AND y > 10;
END_FUNCTION_BLOCK
"""


def classes(driver, testid):
    return (el(driver, testid, reveal=False).get_attribute("class") or "").split()


def open_st(driver, base_url, tmp_path, name="counter.st"):
    open_fresh(driver, base_url)
    path = tmp_path / name
    path.write_text(PROGRAM)
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: el(driver, "machine", reveal=False).get_attribute("value") == "soft-plc",
         message="the page switches to the soft PLC")
    close_menu(driver)
    area = wait(driver, lambda: el(driver, "soft-st-text"))
    wait(driver, lambda: "count := count + 1;" in area.get_attribute("value"), message="the ST text")
    wait(driver, lambda: el(driver, "soft-program-error").text.strip() == "no errors",
         message=el(driver, "soft-program-error", reveal=False).text)
    return area


def value_beside(driver, line):
    """The values beside `line`, scrolled into view first: only the lines
    shown are read."""
    found = el(driver, f"st-value-{line}", reveal=False)
    driver.execute_script("arguments[0].scrollIntoView({block: 'nearest'})", found)
    return found.text


def count_beside(driver, line):
    text = value_beside(driver, line)
    assert text.startswith("count = "), text
    return int(text.split()[2])


def test_an_st_file_opened_runs_with_its_values_beside_the_lines(driver, base_url, tmp_path, artifacts):
    open_st(driver, base_url, tmp_path)
    assert el(driver, "soft-language").get_attribute("value") == "st"
    el(driver, "soft-program-load").click()
    wait(driver, lambda: value_beside(driver, 7).startswith("count = "), message="line 7's value")
    first = count_beside(driver, 7)
    wait(driver, lambda: count_beside(driver, 7) > first + 3, message="live, as it runs")
    wait(driver, lambda: "lamp = TRUE" in value_beside(driver, 8), message="line 8's names")
    assert value_beside(driver, 1) == "", "the POU's name is no variable"
    wait(driver, lambda: value_beside(driver, 3).startswith("count = "), message="a declaration's too")
    # Coloured: the keywords and the comment.
    code = el(driver, "st-editor")
    kinds = [e.text for e in code.find_elements(By.CSS_SELECTOR, ".st-kw")]
    assert "PROGRAM" in kinds and "END_VAR" in kinds, kinds
    assert code.find_elements(By.CSS_SELECTOR, ".st-comment")
    # Kept over a reload, in ST.
    driver.refresh()
    area = wait(driver, lambda: el(driver, "soft-st-text"))
    assert "total := total + count;" in area.get_attribute("value")
    driver.save_screenshot(str(artifacts / "st-running.png"))
    assert severe_console_messages(driver) == []


def test_an_error_is_shown_at_its_line_as_the_user_types(driver, base_url, tmp_path):
    area = open_st(driver, base_url, tmp_path)
    area.click()
    area.send_keys(Keys.CONTROL, Keys.HOME)
    for _ in range(6):
        area.send_keys(Keys.DOWN)
    area.send_keys("y := 1;", Keys.ENTER)
    wait(driver, lambda: "st-error" in classes(driver, "st-line-7"), message="line 7 marked")
    errors = el(driver, "soft-program-error").text
    assert "7:" in errors and "y" in errors, errors
    assert el(driver, "soft-program-load").get_attribute("disabled")
    # Nothing typed is lost or replaced.
    assert "y := 1;\ncount := count + 1;" in area.get_attribute("value")
    # Completion: a declared name from its first letters, on a line of its own.
    area.send_keys(Keys.ENTER, Keys.UP, "to")
    wait(driver, lambda: "total" in el(driver, "st-completions", reveal=False).text)
    area.send_keys(Keys.ENTER)
    assert "y := 1;\ntotal\ncount := count + 1;" in area.get_attribute("value"), area.get_attribute("value")


def test_a_breakpoint_pauses_before_its_line_and_step_moves_the_marked_line(driver, base_url, tmp_path):
    open_st(driver, base_url, tmp_path)
    el(driver, "soft-program-load").click()
    wait(driver, lambda: count_beside(driver, 7) > 2, message="running")
    el(driver, "st-line-8").click()
    assert "st-breakpoint" in classes(driver, "st-line-8")
    wait(driver, lambda: "st-current-line" in classes(driver, "st-line-8"), message="stopped at line 8")
    assert "8" in el(driver, "st-status").text
    assert el(driver, "pause").get_attribute("aria-pressed") == "true", "the page paused"
    stopped = count_beside(driver, 7)
    time.sleep(0.5)
    assert count_beside(driver, 7) == stopped, "the scan stands still"
    el(driver, "st-step").click()
    wait(driver, lambda: "st-current-line" in classes(driver, "st-line-9"), message="on to line 9")
    assert "st-current-line" not in classes(driver, "st-line-8")
    assert count_beside(driver, 7) == stopped, "line 7 did not run again"
    el(driver, "st-step").click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, ".st-line.st-current-line"),
         message="the scan ended")
    el(driver, "st-step").click()
    wait(driver, lambda: "st-current-line" in classes(driver, "st-line-8"), message="the next scan's line 8")
    assert count_beside(driver, 7) == stopped + 1
    # Resumed: it runs on to the breakpoint in the next scan.
    el(driver, "pause").click()
    wait(driver, lambda: count_beside(driver, 7) == stopped + 2, message="next scan's stop")
    assert severe_console_messages(driver) == []


def test_the_st_editor_on_a_laptop_and_a_phone(tmp_path, base_url, artifacts):
    for screen in ["laptop", "phone"]:
        drv = screen_driver(tmp_path / screen, screen)
        try:
            open_st(drv, base_url, tmp_path, f"{screen}.st")
            el(drv, "soft-program-load").click()
            wait(drv, lambda: value_beside(drv, 7).startswith("count = "))
            el(drv, "st-line-8").click()
            wait(drv, lambda: "st-current-line" in classes(drv, "st-line-8"))
            el(drv, "st-step").click()
            wait(drv, lambda: "st-current-line" in classes(drv, "st-line-9"))
            el(drv, "st-editor")
            drv.save_screenshot(str(artifacts / f"st-{screen}.png"))
            # The editor's own findings (the page's others are its parts' own),
            # and the phone's strip under an empty ladder (its note once grey
            # on its dark ground).
            found = [v for v in violations(drv)
                     if any("st-" in n or "io-strip" in n for n in v["nodes"])]
            assert found == [], found
        finally:
            drv.quit()


def settled_text(driver, testid):
    """A control's text, "" while the page draws it anew."""
    try:
        return el(driver, testid).text
    except StaleElementReferenceException:
        return ""


def open_library(driver, base_url, tmp_path, name="blocks.st"):
    """A `.st` file of function blocks only opened: no errors, its block
    offered in the palette."""
    open_fresh(driver, base_url)
    path = tmp_path / name
    path.write_text(LIBRARY)
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: el(driver, "machine", reveal=False).get_attribute("value") == "soft-plc",
         message="the page switches to the soft PLC")
    close_menu(driver)
    wait(driver, lambda: settled_text(driver, "soft-program-error").strip() == "no errors",
         message="a library of blocks loads")
    wait(driver, lambda: el(driver, "palette-st-scale"), message="SCALE in the palette")


def place_scale(driver):
    """%IX0.0 -> [s0: SCALE 5] -> %QX0.0, the box from the palette."""
    focus_ladder(driver)
    place(driver, Keys.F5, "%IX0.0")
    el(driver, "palette-st-scale").click()
    entry = wait(driver, lambda: el(driver, "device-input"))
    assert entry.get_attribute("value") == "SCALE ", entry.get_attribute("value")
    entry.send_keys("s0 5", Keys.ENTER)
    wait(driver, lambda: "SCALE" in el(driver, "cell-0-0-1").text, message="the box placed")
    focus_ladder(driver, "cell-0-0-2")
    place(driver, Keys.F7, "%QX0.0")


def test_an_st_block_called_from_a_ladder_box_gives_its_value_on_the_box(driver, base_url, tmp_path, artifacts):
    open_library(driver, base_url, tmp_path)
    place_scale(driver)
    wait(driver, lambda: el(driver, "problems").text.strip() == "No problems.",
         message=el(driver, "problems", reveal=False).text)
    # The block's IL follows the ladder's in its listing.
    assert "CAL s0(go := " in el(driver, "il-listing").text
    el(driver, "run").click()
    wait(driver, lambda: "y=11" in box_values(driver, "cell-0-0-1"), message="x * 2 + 1 on the box")
    assert "ok=0" in box_values(driver, "cell-0-0-1").replace("FALSE", "0"), box_values(driver, "cell-0-0-1")
    assert not on(driver, "soft-lamp-QX0-0"), "no power into go"
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="go and y > 10: the box passes power")
    driver.save_screenshot(str(artifacts / "st-box-running.png"))
    # The text no longer declares SCALE: an error at the box, the ladder kept.
    area = el(driver, "soft-st-text")
    area.click()
    area.send_keys(Keys.CONTROL, Keys.HOME)
    area.send_keys(Keys.END, "x")
    # Checked 300 ms after the last key, while the pane is shown.
    time.sleep(0.8)
    wait(driver, lambda: "SCALE" in el(driver, "problems").text, message="the box's block is gone")
    assert "SCALE" in el(driver, "cell-0-0-1").text, "the box kept"
    # Named back: no problem.
    area = el(driver, "soft-st-text")
    area.send_keys(Keys.CONTROL, Keys.HOME)
    area.send_keys(Keys.END, Keys.BACKSPACE)
    time.sleep(0.8)
    wait(driver, lambda: el(driver, "problems").text.strip() == "No problems.")
    # Shared: the link carries the ST text (a 6. link); opened in a fresh
    # page, the pane holds it and the box is whole again.
    el(driver, "share").click()
    link = el(driver, "share-url").get_attribute("value")
    assert "/#6." in link, link
    open_fresh(driver, base_url)
    driver.get(link)
    wait(driver, lambda: "SCALE" in settled_text(driver, "cell-0-0-1"), message="the link's ladder")
    wait(driver, lambda: "FUNCTION_BLOCK Scale" in el(driver, "soft-st-text").get_attribute("value"),
         message="the link's ST in the pane")
    wait(driver, lambda: el(driver, "problems").text.strip() == "No problems.",
         message=el(driver, "problems", reveal=False).text)
    assert severe_console_messages(driver) == []


def test_an_st_box_on_a_laptop_and_a_phone(tmp_path, base_url, artifacts):
    for screen in ["laptop", "phone"]:
        drv = screen_driver(tmp_path / screen, screen)
        try:
            open_library(drv, base_url, tmp_path, f"{screen}-blocks.st")
            place_scale(drv)
            el(drv, "run").click()
            wait(drv, lambda: "y=11" in box_values(drv, "cell-0-0-1"))
            el(drv, "cell-0-0-1")
            drv.save_screenshot(str(artifacts / f"st-box-{screen}.png"))
        finally:
            drv.quit()


OWN_XML = (ROOT / "engine/tests/ladder/fixtures/soft-st.xml").read_text()


def plcopen_st_only():
    """Our own PLCopen project (engine/tests/ladder/fixtures/soft-st.xml)
    without its LD program: a program and a block, both in ST."""
    start = OWN_XML.index('<pou name="inline"')
    end = OWN_XML.index("</pou>", start) + len("</pou>")
    text = OWN_XML[:start] + OWN_XML[end:]
    return text.replace('<pouInstance name="inlineInst" typeName="inline"/>', "")


def plcopen_mixed():
    """The same project with its LD program a contact and a coil: LD and ST."""
    start = OWN_XML.index('<block localId="3"')
    end = OWN_XML.index("</block>", start) + len("</block>")
    text = OWN_XML[:start] + OWN_XML[end:]
    return text.replace('<connection refLocalId="3"/></connectionPointIn><connectionPointOut/><variable>seen',
                        '<connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>seen')


def open_plcopen_st(driver, base_url, tmp_path, text, name="project.xml"):
    """A PLCopen project opened on the soft PLC: its ST in the pane."""
    choose_soft(driver, base_url)
    path = tmp_path / name
    path.write_text(text)
    el(driver, "open-file").send_keys(str(path))
    close_menu(driver)
    area = wait(driver, lambda: el(driver, "soft-st-text"))
    wait(driver, lambda: "PROGRAM main" in area.get_attribute("value"), message="the project's ST")
    wait(driver, lambda: el(driver, "soft-program-error").text.strip() == "no errors",
         message=el(driver, "soft-program-error", reveal=False).text)
    return area


def line_holding(area, text):
    """The 1-based line of the pane's text that holds `text`."""
    lines = area.get_attribute("value").split("\n")
    return next(i for i, line in enumerate(lines) if text in line) + 1


def test_a_plcopen_project_in_st_opens_in_the_st_pane_and_runs(driver, base_url, tmp_path, artifacts):
    area = open_plcopen_st(driver, base_url, tmp_path, plcopen_st_only())
    assert el(driver, "soft-language").get_attribute("value") == "st"
    text = area.get_attribute("value")
    assert "FUNCTION_BLOCK Counter" in text and "IF Reset THEN" in text, text
    # Nothing drawn: the ladder is empty, nothing said against the file.
    assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]')
    assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-kind]:not([data-kind=""])')
    el(driver, "run").click()
    line = line_holding(area, "count := c0.OUT;")
    wait(driver, lambda: value_beside(driver, line).startswith("count = "), message="the value beside its line")
    # c0 counts scans until count reaches 10; then the program returns
    # before `count := count * 100`.
    wait(driver, lambda: count_beside(driver, line) >= 10, message="counting, live")
    driver.save_screenshot(str(artifacts / "st-plcopen.png"))
    assert severe_console_messages(driver) == []


def test_a_plcopen_project_mixing_ld_and_st_opens_each_on_its_side(driver, base_url, tmp_path):
    area = open_plcopen_st(driver, base_url, tmp_path, plcopen_mixed(), "mixed.xml")
    assert "PROGRAM inline" not in area.get_attribute("value")
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-kind") == "no",
         message="the LD program on the ladder")
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text


def ask_why_in_the_pane(driver, name):
    """Why? on `name` in the ST pane: the statements listed."""
    field = el(driver, "st-why-name")
    field.clear()
    field.send_keys(name)
    el(driver, "st-why").click()
    return wait(driver, lambda: el(driver, "st-why-result"), message="the answer")


def test_why_on_an_st_programs_variable_names_its_statement_and_operands(driver, base_url, tmp_path):
    open_st(driver, base_url, tmp_path)
    el(driver, "soft-program-load").click()
    wait(driver, lambda: count_beside(driver, 7) > 6, message="running, lamp on")
    result = ask_why_in_the_pane(driver, "lamp")
    items = result.find_elements(By.CSS_SELECTOR, '[data-testid="why-st"]')
    assert [i.get_attribute("data-line") for i in items] == ["8"], result.text
    text = items[0].text
    assert "ST line 8" in text and "lamp := count > 5;" in text, text
    assert "count = " in text and items[0].get_attribute("data-ran") == "1", text
    # Paused, the operand's value is the scan's: the one beside line 7.
    el(driver, "pause").click()
    time.sleep(0.3)
    result = ask_why_in_the_pane(driver, "lamp")
    assert f"count = {count_beside(driver, 7)}" in result.text, result.text
    # A name no statement writes says so.
    assert "No statement of the program writes nothing" in ask_why_in_the_pane(driver, "nothing").text
    assert severe_console_messages(driver) == []


def coil_cell(driver):
    """The coil's cell, shown (on a phone the ladder may sit behind a
    dock)."""
    coil = driver.find_element(By.CSS_SELECTOR, '[data-testid="ladder"] [data-kind="coil"]')
    return el(driver, coil.get_attribute("data-testid"))


def why_into_the_box(driver):
    """The SCALE box's ladder running with go on; Why? on its coil."""
    el(driver, "run").click()
    press = el(driver, "soft-input-IX0-0")
    # On a phone the board's switch sits under the tools' dock: pressed
    # as the board's own handler takes it.
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'}); arguments[0].click()", press)
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="the box passes power")
    coil = coil_cell(driver)
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", coil)
    coil.click()
    driver.switch_to.active_element.send_keys("w")
    wait(driver, lambda: el(driver, "why-head").get_attribute("data-powered") == "1")
    return wait(driver, lambda: driver.find_elements(
        By.CSS_SELECTOR, '[data-testid="why-panel"] [data-testid="why-st"]'), message="the block's statement")


def test_why_on_a_coil_fed_by_an_st_block_follows_into_its_statements(driver, base_url, tmp_path):
    open_library(driver, base_url, tmp_path)
    place_scale(driver)
    found = why_into_the_box(driver)
    assert [f.get_attribute("data-line") for f in found] == ["11"], [f.text for f in found]
    text = found[0].text
    assert "ok := go AND y > 10;" in text, text
    assert "go = TRUE" in text and "y = 11" in text, text
    # The line's button shows the ST pane.
    found[0].find_element(By.CSS_SELECTOR, "button").click()
    wait(driver, lambda: el(driver, "soft-st-text", reveal=False).is_displayed())
    assert severe_console_messages(driver) == []


def test_why_into_st_and_a_plcopen_st_project_on_a_laptop_and_a_phone(tmp_path, base_url, artifacts):
    for screen in ["laptop", "phone"]:
        drv = screen_driver(tmp_path / screen, screen)
        try:
            area = open_plcopen_st(drv, base_url, tmp_path, plcopen_st_only(), f"{screen}.xml")
            el(drv, "run").click()
            line = line_holding(area, "count := c0.OUT;")
            wait(drv, lambda: value_beside(drv, line).startswith("count = "))
            result = ask_why_in_the_pane(drv, "count")
            assert "c0.OUT = " in result.text, result.text
            drv.execute_script("arguments[0].scrollIntoView({block: 'center'})", result)
            drv.save_screenshot(str(artifacts / f"st-plcopen-why-{screen}.png"))
            open_library(drv, base_url, tmp_path, f"{screen}-blocks.st")
            place_scale(drv)
            found = why_into_the_box(drv)
            drv.execute_script("arguments[0].scrollIntoView({block: 'center'})", found[0])
            drv.save_screenshot(str(artifacts / f"st-why-box-{screen}.png"))
            found = [v for v in violations(drv)
                     if any("why" in n or "st-" in n for n in v["nodes"])]
            assert found == [], found
        finally:
            drv.quit()


PICK = """FUNCTION_BLOCK Pick
VAR_INPUT
  go : BOOL;
  x : INT;
END_VAR
VAR_OUTPUT
  ok : BOOL;
  y : INT;
END_VAR
y := x * 2 + 1;
IF go AND y > 10 THEN
  ok := TRUE;
ELSE
  ok := FALSE;
END_IF;
END_FUNCTION_BLOCK
"""


def place_picks(driver, base_url, tmp_path, name="pick.st"):
    """%IX0.0 -> [p0: PICK 5] -> %QX0.0 and %IX0.0 -> [p1: PICK 1] ->
    %QX0.1: one block, two instances; the ladder run."""
    open_fresh(driver, base_url)
    path = tmp_path / name
    path.write_text(PICK)
    el(driver, "open-file").send_keys(str(path))
    close_menu(driver)
    wait(driver, lambda: el(driver, "palette-st-pick"), message="PICK in the palette")
    for rung, x in [(0, 5), (1, 1)]:
        # After a coil the cursor is on the next rung already (on a phone
        # the I/O strip may cover that cell).
        if rung == 0:
            focus_ladder(driver, "cell-0-0-0")
        place(driver, Keys.F5, "%IX0.0")
        el(driver, "palette-st-pick").click()
        wait(driver, lambda: el(driver, "device-input")).send_keys(f"p{rung} {x}", Keys.ENTER)
        wait(driver, lambda: "PICK" in el(driver, f"cell-{rung}-0-1").text, message="the box placed")
        cell = el(driver, f"cell-{rung}-0-2")
        moved = cell.get_attribute("aria-selected") == "true" and \
            driver.switch_to.active_element.get_attribute("data-testid") == "ladder"
        if not moved:
            focus_ladder(driver, f"cell-{rung}-0-2")
        place(driver, Keys.F7, f"%QX0.{rung}")
    wait(driver, lambda: el(driver, "problems").text.strip() == "No problems.",
         message=el(driver, "problems", reveal=False).text)
    el(driver, "run").click()
    el(driver, "st-editor")  # the Program tab shown: its values are read as seen
    wait(driver, lambda: value_beside(driver, 10) == "y = 11  x = 5", message="p0's values beside the line")


def choose_instance(driver, name):
    el(driver, "st-instance").find_element(By.CSS_SELECTOR, f'option[value="{name}"]').click()


def test_an_st_blocks_lines_show_the_chosen_instances_values(driver, base_url, tmp_path):
    place_picks(driver, base_url, tmp_path)
    options = [o.text for o in el(driver, "st-instance").find_elements(By.TAG_NAME, "option")]
    assert options == ["p0 (Pick)", "p1 (Pick)"], options
    assert value_beside(driver, 14) == "ok = FALSE" and value_beside(driver, 12) == "ok = FALSE"
    assert value_beside(driver, 1) == "", "the block's name is no variable"
    choose_instance(driver, "p1")
    wait(driver, lambda: value_beside(driver, 10) == "y = 3  x = 1", message="p1's values")
    assert value_beside(driver, 3) == "go = FALSE", "a declaration's too"
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: value_beside(driver, 3) == "go = TRUE", message="live, as it runs")
    assert value_beside(driver, 12) == "ok = FALSE", "p1: y = 3, not above 10"
    choose_instance(driver, "p0")
    wait(driver, lambda: value_beside(driver, 12) == "ok = TRUE", message="p0: go and y = 11")
    # Time travel: p0's values two scans after the run began, before go.
    el(driver, "pause").click()
    driver.execute_script("const s = arguments[0]; s.value = String(Number(s.min) + 2);"
                          "s.dispatchEvent(new Event('input', {bubbles: true}));", el(driver, "timeline"))
    el(driver, "st-editor")
    wait(driver, lambda: value_beside(driver, 3) == "go = FALSE", message="p0's go at that scan")
    assert value_beside(driver, 12) == "ok = FALSE" and value_beside(driver, 10) == "y = 11  x = 5"
    assert severe_console_messages(driver) == []


def test_a_breakpoint_in_an_st_blocks_body_pauses_the_ladder_and_steps_by_statement(driver, base_url, tmp_path):
    place_picks(driver, base_url, tmp_path)
    el(driver, "st-line-10").click()
    wait(driver, lambda: "st-current-line" in classes(driver, "st-line-10"), message="stopped at line 10")
    assert el(driver, "pause").get_attribute("aria-pressed") == "true", "the page paused"
    status = el(driver, "st-status").text
    assert "line 10" in status and "p0" in status, status
    el(driver, "st-step").click()
    wait(driver, lambda: "st-current-line" in classes(driver, "st-line-11"), message="on to the IF")
    # go is off: the ELSE branch, then out of p0's call, through the
    # ladder's own steps, into p1's call, which the pane then shows.
    el(driver, "st-step").click()
    wait(driver, lambda: "st-current-line" in classes(driver, "st-line-14"), message="the ELSE branch")
    assert "st-current-line" not in classes(driver, "st-line-12")
    el(driver, "st-step").click()
    wait(driver, lambda: "p1" in el(driver, "st-status").text, message="p1's call")
    assert "st-current-line" in classes(driver, "st-line-10")
    assert el(driver, "st-instance").get_attribute("value") == "p1"
    wait(driver, lambda: value_beside(driver, 10) == "y = 3  x = 1", message="p1's values shown")
    # Resumed: on to the breakpoint in the next scan's first call.
    el(driver, "pause").click()
    wait(driver, lambda: "p0" in el(driver, "st-status").text, message="the next scan's p0")
    assert "st-current-line" in classes(driver, "st-line-10")
    assert severe_console_messages(driver) == []


def why_on_coil(driver, n, powered):
    """Why? on the `n`-th coil (its power `powered`, "1" or "0"): the
    block's statements it names."""
    coil = driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-kind="coil"]')[n]
    coil = el(driver, coil.get_attribute("data-testid"))
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", coil)
    coil.click()
    driver.switch_to.active_element.send_keys("w")
    wait(driver, lambda: el(driver, "why-head").get_attribute("data-powered") == powered)
    return wait(driver, lambda: driver.find_elements(
        By.CSS_SELECTOR, '[data-testid="why-panel"] [data-testid="why-st"]'), message="the block's statement")


def test_why_on_a_coil_fed_by_an_st_block_names_the_statement_that_ran(driver, base_url, tmp_path):
    place_picks(driver, base_url, tmp_path)
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="p0 passes power")
    found = why_on_coil(driver, 0, "1")
    assert [(f.get_attribute("data-line"), f.get_attribute("data-ran")) for f in found] == [("12", "1")], \
        [f.text for f in found]
    assert "ok := TRUE;" in found[0].text and "ran in the last scan" in found[0].text, found[0].text
    # p1 (y = 3) took the ELSE branch: its coil's Why? names that one.
    assert not on(driver, "soft-lamp-QX0-1")
    found = why_on_coil(driver, 1, "0")
    assert [(f.get_attribute("data-line"), f.get_attribute("data-ran")) for f in found] == [("14", "1")], \
        [f.text for f in found]
    assert severe_console_messages(driver) == []


def test_an_st_blocks_values_on_a_laptop_and_a_phone(tmp_path, base_url, artifacts):
    for screen in ["laptop", "phone"]:
        drv = screen_driver(tmp_path / screen, screen)
        try:
            place_picks(drv, base_url, tmp_path, f"{screen}-pick.st")
            el(drv, "st-line-10").click()
            wait(drv, lambda: "p0" in el(drv, "st-status").text, message="stopped in p0's call")
            el(drv, "st-editor")
            drv.save_screenshot(str(artifacts / f"st-block-values-{screen}.png"))
            # The instance shown and the call the scan stands in, under the editor.
            drv.execute_script("arguments[0].scrollIntoView({block: 'nearest'})", el(drv, "st-instance"))
            assert "p0" in el(drv, "st-status").text
            drv.save_screenshot(str(artifacts / f"st-block-instance-{screen}.png"))
            found = [v for v in violations(drv)
                     if any("st-" in n or "io-strip" in n for n in v["nodes"])]
            assert found == [], found
        finally:
            drv.quit()


def plcopen_ld_calling_st():
    """A project written here: `Doubler` in ST (y := x * 2 while go) and
    an LD program whose contact %IX0.0 powers `d1: Doubler(x := 21)`,
    its `done` the lamp %QX0.0."""
    st = ('<ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA[done := go;\n'
          'IF go THEN\n  y := x * 2;\nEND_IF;]]></xhtml:p></ST>')
    return f"""<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>
<pou name="Doubler" pouType="functionBlock"><interface>
<inputVars><variable name="go"><type><BOOL/></type></variable><variable name="x"><type><INT/></type></variable></inputVars>
<outputVars><variable name="done"><type><BOOL/></type></variable><variable name="y"><type><INT/></type></variable></outputVars>
</interface><body>{st}</body></pou>
<pou name="main" pouType="program"><interface><localVars>
<variable name="start" address="%IX0.0"><type><BOOL/></type></variable>
<variable name="lamp" address="%QX0.0"><type><BOOL/></type></variable>
<variable name="d1"><type><derived name="Doubler"/></type></variable>
</localVars></interface><body><LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>
<contact localId="2"><position x="20" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>start</variable></contact>
<inVariable localId="3"><position x="20" y="40"/><connectionPointOut/><expression>21</expression></inVariable>
<block localId="4" typeName="Doubler" instanceName="d1"><position x="60" y="0"/>
<inputVariables><variable formalParameter="go"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable><variable formalParameter="x"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable></inputVariables>
<inOutVariables/><outputVariables><variable formalParameter="done"><connectionPointOut/></variable><variable formalParameter="y"><connectionPointOut/></variable></outputVariables></block>
<coil localId="5"><position x="120" y="0"/><connectionPointIn><connection refLocalId="4" formalParameter="done"/></connectionPointIn><connectionPointOut/><variable>lamp</variable></coil>
<rightPowerRail localId="6"><position x="200" y="0"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn></rightPowerRail>
</LD></body></pou>
</pous></types><instances><configurations><configuration name="c"><resource name="r">
<task name="t" priority="0" interval="T#10ms"><pouInstance name="m" typeName="main"/></task>
</resource></configuration></configurations></instances></project>"""


def test_a_plcopen_ld_program_calling_its_st_block_runs_with_the_value_on_the_box(driver, base_url, tmp_path, artifacts):
    choose_soft(driver, base_url)
    path = tmp_path / "doubler.xml"
    path.write_text(plcopen_ld_calling_st())
    el(driver, "open-file").send_keys(str(path))
    close_menu(driver)
    area = wait(driver, lambda: el(driver, "soft-st-text"))
    wait(driver, lambda: "FUNCTION_BLOCK Doubler" in area.get_attribute("value"), message="the block in the pane")
    assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-dialog"]')
    box = wait(driver, lambda: next((c for c in driver.find_elements(By.CSS_SELECTOR, '[data-kind="box"]')
                                     if "DOUBLER" in c.text), None), message="the block drawn as a box")
    cell = box.get_attribute("data-testid")
    wait(driver, lambda: el(driver, "problems").text.strip() == "No problems.",
         message=el(driver, "problems", reveal=False).text)
    el(driver, "run").click()
    assert not on(driver, "soft-lamp-QX0-0"), "no power into go"
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: "y=42" in box_values(driver, cell), message="x * 2 on the box")
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="done follows go: the lamp")
    driver.save_screenshot(str(artifacts / "st-plcopen-box.png"))
    assert severe_console_messages(driver) == []


def two_st_programs():
    """`plcopen_st_only` with a second ST program, `tens`, run first by
    the task, its `count` its own: it adds 10 a scan."""
    tens = ('<pou name="tens" pouType="program"><interface><localVars>'
            '<variable name="count"><type><INT/></type></variable></localVars></interface>'
            '<body><ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA[count := count + 10;]]>'
            '</xhtml:p></ST></body></pou>')
    text = plcopen_st_only().replace("</pous>", tens + "</pous>")
    return text.replace('<pouInstance name="mainInst" typeName="main"/>',
                        '<pouInstance name="t" typeName="tens"/><pouInstance name="mainInst" typeName="main"/>')


def test_two_st_programs_run_each_with_its_own_values_beside_its_lines(driver, base_url, tmp_path):
    area = open_plcopen_st(driver, base_url, tmp_path, two_st_programs(), "two.xml")
    text = area.get_attribute("value")
    assert text.index("PROGRAM tens") < text.index("PROGRAM main"), "in the task's order"
    el(driver, "run").click()
    mains = line_holding(area, "count := c0.OUT;")
    tens = line_holding(area, "count := count + 10;")
    wait(driver, lambda: count_beside(driver, mains) >= 3, message="main counting")
    el(driver, "pause").click()
    # Paused: each line shows its own program's count.
    time.sleep(0.3)
    ten, main = count_beside(driver, tens), count_beside(driver, mains)
    assert ten > 0 and ten % 10 == 0, ten
    assert main != ten, (main, ten)
    assert severe_console_messages(driver) == []
