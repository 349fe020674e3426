"""End-to-end: the soft PLC in the page (issue #31): its board, boxes on
words, the variables pane, sharing, a ladder test on a word."""

import json
import subprocess

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import drawn, el, on, open_fresh, severe_console_messages, wait
from test_ladder import HASHIGO, focus_ladder, keys, place, saved_ladder
from test_import import ROOT


def choose_soft(driver, base_url):
    open_fresh(driver, base_url)
    select = Select(el(driver, "machine"))
    assert "Soft PLC (IEC 61131-3)" in [o.text for o in select.options]
    select.select_by_value("soft-plc")
    wait(driver, lambda: el(driver, "soft-board"))


def measure_level(driver, level):
    """The parts example running, measuring (%IX0.2 on), its level input
    %IW0 set to `level` in the slider's box; the box."""
    el(driver, "run").click()
    el(driver, "soft-input-IX0-2").click()
    box = el(driver, "soft-analog-value-IW0")
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys(level, Keys.ENTER)
    return box


def box_values(driver, cell):
    return el(driver, cell).find_element(By.CSS_SELECTOR, '[data-testid="box-values"]').text


def test_draw_by_keys_run_and_drive_it_from_the_board(driver, base_url, artifacts):
    choose_soft(driver, base_url)
    # A fresh board: 8 inputs and 8 outputs.
    for n in range(8):
        assert el(driver, f"soft-input-IX0-{n}") and el(driver, f"soft-lamp-QX0-{n}")
    focus_ladder(driver)
    place(driver, Keys.F5, "%IX0.0")
    place(driver, Keys.F7, "%QX0.0")
    assert el(driver, "problems").text.strip() == "No problems."
    assert "ST %QX0.0" in el(driver, "il-listing").text
    el(driver, "run").click()
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-on") == "0", message="live")
    assert not on(driver, "soft-lamp-QX0-0")
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="%QX0.0 follows %IX0.0")
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1")
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: not on(driver, "soft-lamp-QX0-0"), message="and drops with it")
    driver.save_screenshot(str(artifacts / "soft-drawn.png"))
    assert severe_console_messages(driver) == []


def test_add_and_gt_boxes_show_their_values_live(driver, base_url, artifacts):
    choose_soft(driver, base_url)
    # Declare the words first: the entry offers them.
    for name in ["count", "level"]:
        el(driver, "var-new-name").send_keys(name)
        el(driver, "var-add").click()
        wait(driver, lambda: el(driver, f"var-{name}"))
    focus_ladder(driver)
    place(driver, Keys.F5, "%IX0.1")
    place(driver, Keys.F8, "ADD count 1 count")
    assert el(driver, "cell-0-0-9").get_attribute("data-kind") == "box"
    # The comparison from the palette: its entry opens with GT typed.
    el(driver, "palette-gt").click()
    entry = wait(driver, lambda: el(driver, "device-input"))
    assert entry.get_attribute("value") == "GT "
    entry.send_keys("count 50", Keys.ENTER)
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "ladder")
    place(driver, Keys.F7, "%QX0.1")
    keys(driver, Keys.F8)
    keys(driver, "lev")
    wait(driver, lambda: "level" in el(driver, "device-options").text, message="declared first")
    assert el(driver, "device-options").text.splitlines()[0].startswith("level")
    keys(driver, Keys.ESCAPE)
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text
    el(driver, "run").click()
    el(driver, "soft-input-IX0-1").click()
    wait(driver, lambda: box_values(driver, "cell-0-0-9").startswith("count="), message="ADD's values")
    wait(driver, lambda: on(driver, "soft-lamp-QX0-1"), timeout=10, message="count passes 50")
    assert box_values(driver, "cell-1-0-0").startswith("count=")
    value = int(box_values(driver, "cell-1-0-0").split("=")[1])
    assert value > 50
    wait(driver, lambda: el(driver, "var-count").find_element(
        By.CSS_SELECTOR, '[data-testid="var-value"]').text not in ("", "0"))
    driver.save_screenshot(str(artifacts / "soft-boxes.png"))
    assert severe_console_messages(driver) == []


def test_declare_rename_and_retype_a_variable(driver, base_url):
    choose_soft(driver, base_url)
    el(driver, "var-new-name").send_keys("total")
    el(driver, "var-add").click()
    wait(driver, lambda: el(driver, "var-total"))
    focus_ladder(driver)
    place(driver, Keys.F5, "%IX0.0")
    place(driver, Keys.F8, "MOVE 42 total")
    place(driver, Keys.F8, "EQ total 42")
    place(driver, Keys.F7, "%QX0.2")
    # Rename: every use follows.
    name = el(driver, "var-total").find_element(By.CSS_SELECTOR, '[data-testid="var-name"]')
    name.send_keys(Keys.CONTROL, "a")
    name.send_keys("parts", Keys.TAB)
    wait(driver, lambda: el(driver, "var-parts"))
    ladder = saved_ladder(driver, "soft-plc")
    text = json.dumps(ladder)
    assert "total" not in text and text.count("parts") >= 3, text
    # Retype to BOOL: MOVE 42 no longer fits, refused at its cell.
    kind = el(driver, "var-parts").find_element(By.CSS_SELECTOR, '[data-testid="var-type"]')
    kind.send_keys(Keys.CONTROL, "a")
    kind.send_keys("BOOL", Keys.TAB)
    wait(driver, lambda: "rung 1" in el(driver, "variables-error").text)
    assert saved_ladder(driver, "soft-plc")["variables"][0]["type"] == "INT"
    type_field = el(driver, "var-parts").find_element(By.CSS_SELECTOR, '[data-testid="var-type"]')
    assert type_field.get_attribute("value") == "INT", "the field shows what is declared"
    # A value set from the pane: the program writes 42 only while %IX0.0 is on.
    el(driver, "run").click()
    row = el(driver, "var-parts")
    row.find_element(By.CSS_SELECTOR, '[data-testid="var-set"]').send_keys("7", Keys.ENTER)
    wait(driver, lambda: el(driver, "var-parts").find_element(
        By.CSS_SELECTOR, '[data-testid="var-value"]').text == "7", message="set to 7")
    el(driver, "soft-input-IX0-0").click()
    wait(driver, lambda: el(driver, "var-parts").find_element(
        By.CSS_SELECTOR, '[data-testid="var-value"]').text == "42", message="MOVE 42 writes it")
    wait(driver, lambda: on(driver, "soft-lamp-QX0-2"), message="EQ parts 42")
    # An unused variable can go; a used one cannot.
    el(driver, "var-new-name").send_keys("spare")
    el(driver, "var-add").click()
    wait(driver, lambda: el(driver, "var-spare"))
    el(driver, "var-spare").find_element(By.CSS_SELECTOR, '[data-testid="var-remove"]').click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="var-spare"]'))
    el(driver, "var-parts").find_element(By.CSS_SELECTOR, '[data-testid="var-remove"]').click()
    wait(driver, lambda: "rung 1" in el(driver, "variables-error").text, message="parts is used")
    # A comment is kept, and undo takes it back.
    comment = el(driver, "var-parts").find_element(By.CSS_SELECTOR, '[data-testid="var-comment"]')
    comment.send_keys("parts made", Keys.TAB)
    wait(driver, lambda: saved_ladder(driver, "soft-plc")["variables"][0].get("comment") == "parts made")
    el(driver, "undo").click()
    wait(driver, lambda: "comment" not in saved_ladder(driver, "soft-plc")["variables"][0])


def test_a_soft_plc_ladder_shared_to_a_fresh_profile(driver, base_url):
    choose_soft(driver, base_url)
    Select(el(driver, "example")).select_by_value("parts")
    wait(driver, lambda: el(driver, "var-parts"))
    el(driver, "share").click()
    link = el(driver, "share-url").get_attribute("value")
    assert link.startswith(base_url + "/#3."), link
    shared = saved_ladder(driver, "soft-plc")
    project = json.loads(subprocess.run([str(HASHIGO), "unshare", link], check=True,
                                        capture_output=True, text=True).stdout)
    assert project["machine"] == "soft-plc" and project["ladder"] == shared
    # A fresh profile opens it on the soft PLC, variables and boxes.
    open_fresh(driver, base_url)
    driver.get(link)
    wait(driver, lambda: el(driver, "shared-banner"))
    assert Select(el(driver, "machine")).first_selected_option.get_attribute("value") == "soft-plc"
    wait(driver, lambda: el(driver, "var-parts") and el(driver, "var-level"))
    assert any(c.get_attribute("data-kind") == "box"
               for c in driver.find_elements(By.CSS_SELECTOR, '[data-kind="box"]'))
    # It runs: the level typed by the slider, scaled to percent, on the gauge.
    measure_level(driver, "900")
    wait(driver, lambda: el(driver, "soft-gauge-QW0").get_attribute("data-value") == "90",
         message="90 % on the gauge")
    wait(driver, lambda: on(driver, "soft-lamp-QX0-1"), message="above 80 %")
    # A value an INT does not hold is refused, the input left as it was.
    box = el(driver, "soft-analog-value-IW0")
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys("40000", Keys.ENTER)
    wait(driver, lambda: "40000" in el(driver, "soft-analog-error-IW0").text)
    assert el(driver, "soft-gauge-QW0").get_attribute("data-value") == "90"
    row = el(driver, "var-level_in")
    row.find_element(By.CSS_SELECTOR, '[data-testid="var-set"]').send_keys("many", Keys.ENTER)
    wait(driver, lambda: "many" in row.find_element(By.CSS_SELECTOR, '[data-testid="var-set-error"]').text)


def test_a_ladder_test_on_a_word_passes_in_the_tests_pane(driver, base_url):
    choose_soft(driver, base_url)
    Select(el(driver, "example")).select_by_value("parts")
    wait(driver, lambda: el(driver, "var-parts"))
    el(driver, "tests-open").click()
    wait(driver, lambda: el(driver, "add-test")).click()
    case = wait(driver, lambda: el(driver, "test-case-0"))
    events = "".join(f"{t / 10}s,sensor,{t % 2 == 0 and 1 or 0}\n" for t in range(1, 25))
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-events"]').send_keys(events)
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]').send_keys(
        "parts = 12 at 3s\nbatch = 1 at 3s")
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "pass",
         message=el(driver, "test-case-0").text)
    expect = el(driver, "test-case-0").find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]')
    expect.send_keys("\nparts = 11 at 3s")
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "fail")
    assert "parts was 12" in el(driver, "test-case-0").text


def test_why_a_comparison_blocks_power_says_its_operands_values(driver, base_url):
    choose_soft(driver, base_url)
    Select(el(driver, "example")).select_by_value("parts")
    wait(driver, lambda: el(driver, "var-level"))
    value = measure_level(driver, "500")
    wait(driver, lambda: el(driver, "soft-gauge-QW0").get_attribute("data-value") == "50")
    assert not on(driver, "soft-lamp-QX0-1")
    el(driver, "cell-2-0-9").click()
    driver.switch_to.active_element.send_keys("w")
    wait(driver, lambda: el(driver, "why-head").get_attribute("data-powered") == "0")
    causes = driver.find_elements(By.CSS_SELECTOR, '[data-testid="why-cause"]')
    text = " ".join(c.text for c in causes)
    assert "level = 50" in el(driver, "why-values").text, text
    assert "GT" in text and "driven from outside" not in text, "a box is no input"
    # Time travel: back to a scan before the level was set, the box said 0.
    driver.switch_to.active_element.send_keys(Keys.ESCAPE)
    el(driver, "break-input").send_keys("high rises", Keys.ENTER)
    value.send_keys(Keys.CONTROL, "a")
    value.send_keys("900", Keys.ENTER)
    wait(driver, lambda: "Stopped" in el(driver, "break-status").text or el(driver, "break-status").text,
         message="the break on high")
    wait(driver, lambda: box_values(driver, "cell-2-0-0") == "level=90")
    el(driver, "step-back").click()
    wait(driver, lambda: box_values(driver, "cell-2-0-0") == "level=50", message="the scan before")
    assert el(driver, "soft-gauge-QW0").get_attribute("data-value") == "50", "the board shows that scan"


def test_a_soft_plc_project_keeps_its_variables_and_the_watch_shows_words(driver, base_url):
    choose_soft(driver, base_url)
    el(driver, "projects-open").click()
    el(driver, "project-name").send_keys("Tank")
    el(driver, "project-new").click()
    wait(driver, lambda: el(driver, "project-open-name").text == "Tank")
    Select(el(driver, "example")).select_by_value("parts")
    wait(driver, lambda: el(driver, "var-parts"))
    [entry] = json.loads(driver.execute_script("return localStorage.getItem('hashigo.projects.v1')"))["projects"]
    assert entry["machine"] == "soft-plc"
    saved = lambda: json.loads(driver.execute_script(
        "return localStorage.getItem(arguments[0])", f"hashigo.project.{entry['id']}.v1"))["ladder"]
    wait(driver, lambda: "parts" in [v["name"] for v in saved().get("variables", [])])
    # A reload opens the soft PLC with the project, variables and all.
    driver.refresh()
    wait(driver, lambda: el(driver, "var-level"))
    measure_level(driver, "640")
    el(driver, "watch-input").send_keys("level", Keys.ENTER)
    wait(driver, lambda: el(driver, "watch-level").text.split()[:2] == ["level", "64"], message="a word in the watch")
    assert "(" not in el(driver, "watch-level").text, "a word has no current value apart"


def test_a_soft_plc_ladder_goes_out_as_json_plcopen_text_and_pictures(driver, base_url, tmp_path):
    from test_ladder import CAPTURE, downloads, steps
    choose_soft(driver, base_url)
    Select(el(driver, "example")).select_by_value("parts")
    wait(driver, lambda: el(driver, "var-parts"))
    driver.execute_script(CAPTURE)
    for button in ["save-json", "export-plcopen", "export-text", "export-svg", "export-png"]:
        el(driver, button).click()
    got = downloads(driver, 5)
    project = json.loads(got["soft-plc-ladder.json"])
    assert project["machine"] == "soft-plc" and project["ladder"] == saved_ladder(driver, "soft-plc")
    xml = got["soft-plc-ladder.xml"]
    assert "<project" in xml and "level_in" in xml and "CTU" in xml
    assert steps(got["soft-plc-ladder.txt"]) == steps(el(driver, "il-listing").text)
    assert got["soft-plc-ladder.svg"].startswith("<svg") and "GT level" in got["soft-plc-ladder.svg"]
    # Opened again on the soft PLC: the same program, drawn with its boxes
    # and variables (one undo away from the ladder before).
    before = steps(el(driver, "il-listing").text)
    el(driver, "new-ladder").click()
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="var-parts"]'))
    path = tmp_path / "parts.xml"
    path.write_text(xml)
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: drawn(driver, "var-parts"),
         message="the project's variables in the pane")
    assert steps(el(driver, "il-listing").text) == before
    assert el(driver, "problems").text.strip() == "No problems."
    assert severe_console_messages(driver) == []


WORDS = ROOT / "engine/tests/ladder/fixtures/soft-words.xml"


def test_a_plcopen_project_with_word_blocks_opens_drawn_and_runs(driver, base_url, artifacts):
    """An FBD project of word functions (MUL, INT_TO_DINT, SEL, DIV, GT, a
    three-input EQ) opens on the soft PLC as boxes with their operands and
    the project's variables, and runs: the boxes show their values."""
    choose_soft(driver, base_url)
    el(driver, "open-file").send_keys(str(WORDS))
    wait(driver, lambda: drawn(driver, "var-big"),
         message="the project's variables")
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text
    kinds = [b.text for b in driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-kind="box"]')]
    for kind in ["MUL", "INT_TO_DINT", "SEL", "GT"]:
        assert any(kind in k for k in kinds), (kind, kinds)
    el(driver, "run").click()
    box = el(driver, "soft-analog-value-IW0")
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys("40", Keys.ENTER)
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="40 * 3 > 100: alarm")
    wait(driver, lambda: el(driver, "var-big").find_element(By.CSS_SELECTOR, '[data-testid="var-value"]').text == "40000",
         message="INT_TO_DINT then MUL, into big")
    # The first rung: MUL with its EN on the rail, always powered; Why?
    # on it says so.
    mul = el(driver, "cell-0-0-9")
    assert "MUL" in mul.text and "level" in mul.text, mul.text
    assert el(driver, "cell-0-0-0").get_attribute("data-kind") == "hwire"
    wait(driver, lambda: "=120" in box_values(driver, "cell-0-0-9"), message="40 * 3 live")
    mul.click()
    driver.switch_to.active_element.send_keys("w")
    wait(driver, lambda: el(driver, "why-head").get_attribute("data-powered") == "1")
    driver.save_screenshot(str(artifacts / "soft-words-opened.png"))
    assert severe_console_messages(driver) == []


def test_a_counters_reset_is_wired_as_a_network_below_the_box(driver, base_url, artifacts):
    choose_soft(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "%IX0.0")
    place(driver, Keys.F8, "CTU c0 - 3")
    place(driver, Keys.F7, "%QX0.0")
    # Below the box: %IX0.1 wired into its R.
    focus_ladder(driver, "cell-0-1-0")
    place(driver, Keys.F5, "%IX0.1")
    el(driver, "palette-pin").click()
    entry = wait(driver, lambda: el(driver, "device-input"))
    entry.send_keys("R", Keys.ENTER)
    wait(driver, lambda: el(driver, "cell-0-1-1").get_attribute("data-kind") == "box-input")
    assert "R" in el(driver, "cell-0-1-1").text
    assert el(driver, "problems").text.strip() == "No problems.", el(driver, "problems").text
    el(driver, "run").click()
    for n in range(3):
        el(driver, "soft-input-IX0-0").click()
        wait(driver, lambda: f"CV={n + 1}" in box_values(driver, "cell-0-0-1"), message=f"part {n + 1}")
        el(driver, "soft-input-IX0-0").click()
        wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-on") == "0")
    wait(driver, lambda: on(driver, "soft-lamp-QX0-0"), message="three parts counted")
    assert "CV=3" in box_values(driver, "cell-0-0-1")
    el(driver, "soft-input-IX0-1").click()
    wait(driver, lambda: not on(driver, "soft-lamp-QX0-0"), message="the network below resets it")
    wait(driver, lambda: "CV=0" in box_values(driver, "cell-0-0-1"))
    wait(driver, lambda: el(driver, "cell-0-1-1").get_attribute("data-powered") == "1",
         message="the input's cell shows its network's power")
    # Why? follows into the network: the input has power through %IX0.1.
    el(driver, "cell-0-1-1").click()
    driver.switch_to.active_element.send_keys("w")
    wait(driver, lambda: el(driver, "why-head").get_attribute("data-powered") == "1")
    assert el(driver, "why-head").text.startswith("box input R")
    devices = [c.get_attribute("data-device") for c in driver.find_elements(By.CSS_SELECTOR, '[data-testid="why-cause"]')]
    assert devices == ["%IX0.1"], devices
    driver.save_screenshot(str(artifacts / "soft-reset-network.png"))
    assert severe_console_messages(driver) == []
