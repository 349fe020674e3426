"""End-to-end: Japanese everywhere in the page (issue #49). In Japanese
mode one error of each family the engine makes — a placement refused by
the editor, a wiring problem in Listing & problems, a soft PLC program
that does not compile, a PLCopen file that does not import, a test that
fails — is said in Japanese, with no English sentence (device names,
mnemonics and what the user or the file wrote aside). The command line
stays English; the English page says the engine's own words."""

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.support.ui import Select

from test_app import el, open_fresh, wait
from test_ladder import focus_ladder, keys, place


def english_run(text):
    """The first run of three English words joined by spaces only (a
    capital allowed first; device names, mnemonics and keywords are upper
    case or carry digits; punctuation after a word ends the run): the
    rule of app/src/i18n/errors/mod.rs `english_run`."""
    run = []
    for token in text.split():
        bare = token.rstrip(",.;:)")
        word = bool(bare) and bare[0].isascii() and bare[0].isalpha() and all(
            c.isascii() and (c.islower() or c == "'") for c in bare[1:])
        if not word:
            run = []
            continue
        run.append(bare)
        if len(run) >= 3:
            return " ".join(run)
        if bare != token:
            run = []
    return None


def japanese(text):
    assert text.strip(), "something is said"
    assert any(ord(c) > 0x3000 for c in text), text
    assert english_run(text) is None, f"{english_run(text)!r} in {text!r}"
    return text


def problems(driver):
    """The problems listed, the Listing & problems tab shown."""
    return [p.text for p in el(driver, "problems").find_elements(By.CSS_SELECTOR, ".problem")]


def test_the_rule_finds_english_and_lets_names_be():
    assert english_run("rung 1: the rung has no output") == "the rung has"
    assert english_run("Y00 = 1 at 100ms: Y00 は 100ms に 0 でした") is None
    assert english_run("CAL TON0(IN := %IX0.0, PT := T#5s)") is None


def on(driver, base_url, machine):
    open_fresh(driver, base_url, lang="ja")
    Select(el(driver, "machine")).select_by_value(machine)
    wait(driver, lambda: el(driver, "palette"))


def test_placement_and_wiring_errors_are_japanese(driver, base_url, artifacts):
    on(driver, base_url, "io86a")
    el(driver, "new-ladder").click()
    focus_ladder(driver)
    # An OR branch on the top row: the editor refuses it at the entry.
    ActionChains(driver).key_down(Keys.SHIFT).send_keys(Keys.F5).key_up(Keys.SHIFT).perform()
    keys(driver, "X00", Keys.ENTER)
    wait(driver, lambda: el(driver, "device-error").text != "")
    assert "OR 分岐" in japanese(el(driver, "device-error").text)
    keys(driver, Keys.ESCAPE)
    # A contact with no coil: the rung has no output, in the problems.
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "ladder")
    place(driver, Keys.F5, "X00")
    said = japanese(wait(driver, lambda: problems(driver))[0])
    assert said.startswith("回路 1: 回路に出力がありません"), said
    # A contact on the free row, joined to nothing: dangling, at its cell.
    place(driver, Keys.F7, "Y00")
    el(driver, "cell-0-1-2").click()
    place(driver, Keys.F5, "X01")
    said = wait(driver, lambda: problems(driver))
    assert said[0].startswith("回路 1、行 2、列 3: 浮いています"), said
    assert "浮いています" in el(driver, "cell-0-1-2").get_attribute("title")
    for p in said:
        japanese(p)
    driver.save_screenshot(str(artifacts / "japanese-problems-1366.png"))


def test_a_soft_plc_program_error_is_japanese(driver, base_url):
    on(driver, base_url, "soft-plc")
    text = el(driver, "soft-program-text")
    text.clear()
    text.send_keys("PROGRAM p\nVAR\n  a : BOOL;\nEND_VAR\n  LD\n  FOO a\nEND_PROGRAM\n")
    wait(driver, lambda: "LD" in el(driver, "soft-program-error").text)
    said = el(driver, "soft-program-error").text
    for line in said.splitlines():
        japanese(line)
    assert "`LD` にはオペランドが必要です" in said, said
    assert "不明な命令 `FOO`" in said, said


def test_a_soft_plc_type_problem_is_japanese(driver, base_url):
    """A SEL of two types and a shift of a REAL: the loader's kinds
    (TypeWhy), said in Japanese, not its English words."""
    on(driver, base_url, "soft-plc")
    text = el(driver, "soft-program-text")
    text.clear()
    text.send_keys(
        "PROGRAM p\nVAR\n  b : BOOL;\n  i : INT;\n  r : REAL;\nEND_VAR\n"
        "  LD b\n  SEL i, r\n  ST i\n  LD r\n  SHL 1\n  ST r\nEND_PROGRAM\n")
    wait(driver, lambda: "SEL" in el(driver, "soft-program-error").text)
    said = el(driver, "soft-program-error").text
    for line in said.splitlines():
        japanese(line)
    assert "SEL の 2 つの値は同じ型にしてください" in said, said
    assert "SHL, SHR, ROL, ROR は整数を整数ぶんシフトします" in said, said
    assert "SEL's two values" not in said, said


def test_a_plcopen_import_error_is_japanese(driver, base_url, tmp_path):
    path = tmp_path / "broken.xml"
    path.write_text("<project>\n<a>\n</project>\n")
    on(driver, base_url, "io86a")
    el(driver, "open-file").send_keys(str(path))
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="import-error"]'),
         message="the file's error is shown")
    said = japanese(el(driver, "import-error").text)
    assert said.startswith("broken.xml:3: XML の形が正しくありません"), said


def failing_test(driver, base_url):
    """An IO86A case that fails on the empty ladder, run; what it says."""
    on(driver, base_url, "io86a")
    el(driver, "new-ladder").click()
    el(driver, "tests-open").click()
    wait(driver, lambda: el(driver, "add-test")).click()
    case = wait(driver, lambda: el(driver, "test-case-0"))
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-events"]').send_keys("0ms,X00,1\n")
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]').send_keys("Y00 = 1 at 100ms", Keys.TAB)
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "fail")
    return el(driver, "test-result").text


def test_a_failed_test_and_a_test_error_are_japanese(driver, base_url, artifacts):
    driver.set_window_size(1366, 768)
    said = japanese(failing_test(driver, base_url))
    assert "Y00 は 100ms に 0 でした" in said, said
    # A new case is named in the page's language.
    name = el(driver, "test-case-0").find_element(By.CSS_SELECTOR, '[data-testid="test-name"]')
    assert name.get_attribute("value") == "ケース 1"
    driver.execute_script(
        "document.querySelector('[data-testid=test-result]').scrollIntoView({block: 'center'})")
    driver.save_screenshot(str(artifacts / "japanese-test-fail-1366.png"))
    # A device the machine lacks: the case cannot run, said in Japanese.
    expect = el(driver, "test-case-0").find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]')
    expect.clear()
    expect.send_keys("Y99 = 1 at 100ms", Keys.TAB)
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "error")
    said = el(driver, "test-case-0").text
    assert "期待 1" in said, said
    japanese(said.split("期待 1", 1)[1])


def test_the_english_page_keeps_the_engines_words(driver, base_url):
    open_fresh(driver, base_url, lang="en")
    Select(el(driver, "machine")).select_by_value("io86a")
    wait(driver, lambda: el(driver, "palette"))
    el(driver, "new-ladder").click()
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    said = wait(driver, lambda: problems(driver))
    assert said[0] == "rung 1: the rung has no output: end it with a coil or an output box", said


def test_a_failed_test_in_japanese_on_a_phone(tmp_path, base_url, artifacts):
    from test_screens import no_sideways_overflow, screen_driver

    driver = screen_driver(tmp_path, "phone")
    try:
        said = japanese(failing_test(driver, base_url))
        assert "Y00 は 100ms に 0 でした" in said, said
        driver.execute_script(
            "document.querySelector('[data-testid=test-result]').scrollIntoView({block: 'center'})")
        assert no_sideways_overflow(driver)
        driver.save_screenshot(str(artifacts / "japanese-test-fail-phone.png"))
    finally:
        driver.quit()


def test_a_minasec_program_text_error_is_japanese(driver, base_url):
    open_fresh(driver, base_url, lang="ja")
    el(driver, "program-text").send_keys("LD X00\nLD X09\nFOO Y00\n")
    errors = wait(driver, lambda: el(driver, "program-error"))
    wait(driver, lambda: "X09" in errors.text and "FOO" in errors.text)
    for line in errors.text.splitlines():
        japanese(line)
    assert "不明な命令 \"FOO\"" in errors.text, errors.text


def test_an_io86a_program_text_error_is_japanese(driver, base_url):
    open_fresh(driver, base_url, lang="ja")
    Select(el(driver, "machine")).select_by_value("io86a")
    text = el(driver, "io86a-program-text")
    text.clear()
    text.send_keys("1 LD X00\n2 FOO Y00\n3 OUT T00\n")
    errors = wait(driver, lambda: el(driver, "io86a-program-error"))
    wait(driver, lambda: "FOO" in errors.text and "K10" in errors.text)
    for line in errors.text.splitlines():
        japanese(line)
    assert "不明な命令 \"FOO\"" in errors.text, errors.text


def test_a_program_with_no_ladder_form_is_japanese(driver, base_url):
    """Load as ladder of IO86A's SETS: the step with no ladder form is a
    kind (StepWhy), said in Japanese, and nothing changes."""
    on(driver, base_url, "io86a")
    text = el(driver, "io86a-program-text")
    text.clear()
    text.send_keys("LD X00\nSETS Y00\nEND\n")
    el(driver, "load-as-ladder").click()
    said = wait(driver, lambda: el(driver, "edit-message").text.strip())
    japanese(said)
    assert "SETS / RSTS は 2 つ目のデバイスを駆動します" in said, said


def test_the_plant_dock_in_japanese_says_no_english_sentence(driver, base_url, tmp_path, artifacts):
    """The plants (issue #52): their names, signals, quantities and alarms
    in Japanese; the wiring table keeps the engine's signal names (what
    wiring files and tests write) beside the Japanese words."""
    from test_plant import choose, fill_always, link_of

    fragment = link_of(fill_always(), tmp_path)
    open_fresh(driver, base_url, lang="ja")
    driver.get(f"{base_url}/#{fragment}")
    wait(driver, lambda: el(driver, "cell-0-0-0", reveal=False), message="the ladder opens")
    choose(driver, "tank")
    Select(el(driver, "speed")).select_by_value("10")
    el(driver, "run").click()
    wait(driver, lambda: "raised" in el(driver, "plant-alarm").get_attribute("class"), timeout=30,
         message="the overflow alarm")
    alarm = japanese(el(driver, "plant-alarm").text)
    assert alarm.startswith("警報 ") and "あふれ" in alarm, alarm
    assert "給水弁" in el(driver, "plant-sig-fill").text
    for line in el(driver, "plant").text.splitlines():
        assert english_run(line) is None, line
    driver.save_screenshot(str(artifacts / "japanese-plant-tank-1366.png"))
    # A plant drawn as its signals' lamps.
    choose(driver, "door")
    wait(driver, lambda: "リモコン" in el(driver, "plant-sig-remote").text)
    for line in el(driver, "plant").text.splitlines():
        assert english_run(line) is None, line
