"""End-to-end: the first five minutes (issue #47). A fresh profile opening
the bare page sees the start screen, one opening a share link does not;
the guided first rung, followed by keys at 1366x768 and by taps on a
phone, draws a start/stop self-hold that latches and releases; Escape
leaves the tour; Help opens the guide in English and Japanese, and after
one visit it opens with the server gone. Screenshots of each step go to
artifacts/start-*.png."""

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import el, on, severe_console_messages, wait
from test_ladder import first_visit_kept_offline, keys, one_rung_link, place
from test_screens import screen_driver, tap_entry


def shown(driver, testid):
    return any(e.is_displayed() for e in driver.find_elements(By.CSS_SELECTOR, f'[data-testid="{testid}"]'))


def step(driver):
    return el(driver, "tour-step", reveal=False).get_attribute("data-step")


def wait_step(driver, name):
    wait(driver, lambda: step(driver) == name, message=f"the tour reaches {name} (at {step(driver)})")


@pytest.mark.first_visit
def test_a_fresh_profile_opens_on_the_start_screen_a_share_link_does_not(driver, base_url, artifacts, tmp_path):
    driver.get(base_url)
    wait(driver, lambda: shown(driver, "start-draw"), message="the start screen with its choices")
    for testid in ["start-example", "start-open", "start-exercise", "start-machine-soft-plc"]:
        assert shown(driver, testid), testid
    # The machine's card is the one chosen; another card changes machine.
    wait(driver, lambda: el(driver, "start-machine-minasec-u").get_attribute("aria-pressed") == "true")
    el(driver, "start-machine-io86a").click()
    wait(driver, lambda: el(driver, "machine").get_attribute("value") == "io86a")
    assert el(driver, "start-machine-minasec-u").get_attribute("aria-pressed") == "false"
    # The gallery shows this machine's examples, each with its picture.
    el(driver, "start-example").click()
    wait(driver, lambda: shown(driver, "start-example-io86a-timer"))
    assert not shown(driver, "start-example-minasec-u-seed-test")
    picture = el(driver, "start-example-io86a-timer").find_element(By.TAG_NAME, "img")
    wait(driver, lambda: driver.execute_script("return arguments[0].naturalWidth > 0", picture),
         message="the example's picture loads")
    driver.save_screenshot(str(artifacts / "start-gallery.png"))
    el(driver, "start-example-io86a-timer").click()
    wait(driver, lambda: not shown(driver, "start"), message="an example chosen closes the start screen")
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-device="T00"]'),
         message="the example opens")
    # The app bar names what is open, not "Untitled".
    assert el(driver, "app-project").text == "Manual: timer OUT T00 K19"
    # Regression: the screen's own work after the click (marking the
    # machine's card a frame later) met its disposed screen and the page
    # crashed ("An internal error occurred").
    driver.execute_script("return new Promise((done) => requestAnimationFrame(() => setTimeout(done, 300)))")
    assert not driver.find_elements(By.CSS_SELECTOR, ".fatal"), "the page did not crash"
    assert severe_console_messages(driver) == []
    # Closed for good: not on the next visit; Help brings it back.
    driver.refresh()
    wait(driver, lambda: el(driver, "ladder"))
    assert not shown(driver, "start")
    el(driver, "help-start").click()
    wait(driver, lambda: shown(driver, "start-draw"))
    el(driver, "start-close").click()
    assert not shown(driver, "start")

    # Another fresh profile, opening a share link: no start screen.
    fragment = one_rung_link("minasec-u", "X03", "Y02")
    other = screen_driver(tmp_path / "other", "laptop", first_visit=True)
    try:
        other.get(f"{base_url}/#{fragment}")
        wait(other, lambda: el(other, "shared-banner"))
        assert el(other, "cell-0-0-1").get_attribute("data-device") == "Y02"
        assert not shown(other, "start")
    finally:
        other.quit()


def follow_the_tour(driver, artifacts, name, touch):
    """Starts the tour from the start screen and follows it to the end,
    drawing by keys or by taps and pressing the inputs, checking the lamp."""
    wait(driver, lambda: shown(driver, "start-draw"))
    driver.save_screenshot(str(artifacts / f"start-{name}-0-start.png"))
    el(driver, "start-draw").click()
    wait(driver, lambda: not shown(driver, "start"))
    wait_step(driver, "intro")
    driver.save_screenshot(str(artifacts / f"start-{name}-1-intro.png"))
    el(driver, "tour-next").click()
    wait_step(driver, "contact")
    drawn = [("contact", "palette-no", Keys.F5, "X00"), ("stop", "palette-nc", Keys.F6, "X01"),
             ("coil", "palette-coil", Keys.F7, "Y00")]
    if touch:
        el(driver, "cell-0-0-0").click()
    else:
        assert driver.switch_to.active_element.get_attribute("data-testid") == "ladder", "the tour focused the ladder"
    for i, (now, palette, key, device) in enumerate(drawn):
        wait_step(driver, now)
        driver.save_screenshot(str(artifacts / f"start-{name}-{2 + i}-{now}.png"))
        if touch:
            tap_entry(driver, palette, device)
        else:
            place(driver, key, device)
    wait_step(driver, "hold")
    driver.save_screenshot(str(artifacts / f"start-{name}-5-hold.png"))
    # The tour put the cursor under X00, where the branch goes.
    assert el(driver, "cell-0-1-0").get_attribute("aria-selected") == "true"
    if touch:
        el(driver, "cell-0-1-0").click()
        tap_entry(driver, "palette-or-no", "Y00")
    else:
        place(driver, Keys.F5, "Y00", shift=True)
    wait_step(driver, "run")
    driver.save_screenshot(str(artifacts / f"start-{name}-6-run.png"))
    el(driver, "run").click()
    wait_step(driver, "press")
    start, stop = ("strip-in-X00", "strip-in-X01") if touch else ("input-X00", "input-X01")
    lamp = "strip-out-Y00" if touch else "lamp-Y00"
    lit = (lambda: el(driver, lamp).get_attribute("data-on") == "1") if touch else (lambda: on(driver, lamp))
    assert not lit()
    el(driver, start).click()
    wait_step(driver, "release")
    assert lit(), "Y00 comes on"
    driver.save_screenshot(str(artifacts / f"start-{name}-7-release.png"))
    el(driver, start).click()
    wait_step(driver, "halt")
    assert lit(), "Y00 holds itself"
    el(driver, stop).click()
    wait_step(driver, "done")
    assert not lit(), "Y00 drops out"
    driver.save_screenshot(str(artifacts / f"start-{name}-8-done.png"))
    el(driver, "tour-next").click()
    wait(driver, lambda: not shown(driver, "tour"))


@pytest.mark.parametrize("name,touch", [("laptop", False), ("phone", True)])
def test_the_tour_by_keys_at_1366x768_and_by_taps_on_a_phone_draws_a_self_hold_that_latches(
        base_url, artifacts, tmp_path, name, touch):
    driver = screen_driver(tmp_path, name, first_visit=True)
    try:
        driver.get(base_url)
        follow_the_tour(driver, artifacts, name, touch)
    finally:
        driver.quit()


def test_escape_leaves_the_tour_at_any_step(driver, base_url):
    driver.get(base_url)
    wait(driver, lambda: el(driver, "ladder"))
    el(driver, "help-tour").click()
    wait_step(driver, "intro")
    el(driver, "tour-next").click()
    wait_step(driver, "contact")
    place(driver, Keys.F5, "X00")
    wait_step(driver, "stop")
    keys(driver, Keys.ESCAPE)
    wait(driver, lambda: not shown(driver, "tour"), message="Escape leaves the tour")
    # What was drawn stays.
    assert el(driver, "cell-0-0-0").get_attribute("data-device") == "X00"


def section_in_view(driver, section):
    return driver.execute_script(
        "const g = document.querySelector('[data-testid=guide]').getBoundingClientRect();"
        "const s = document.querySelector('[data-testid=guide] [id=' + arguments[0] + ']');"
        "if (!s) return false; const b = s.getBoundingClientRect();"
        "return b.top >= g.top - 1 && b.top < g.top + g.height / 2;", section)


def guide_lang(driver):
    return driver.execute_script(
        "const a = document.querySelector('[data-testid=guide] article'); return a && a.lang")


def test_help_opens_the_guide_in_both_languages_and_a_pane_opens_its_section(driver, base_url, artifacts):
    driver.get(base_url)
    wait(driver, lambda: el(driver, "ladder"))
    el(driver, "help-guide").click()
    wait(driver, lambda: guide_lang(driver) == "en", message="the English guide")
    for section in ["drawing", "running", "tests", "why", "sharing", "files", "minasec-u", "soft-plc"]:
        assert driver.find_elements(By.CSS_SELECTOR, f'[data-testid="guide"] [id="{section}"]'), section
    driver.save_screenshot(str(artifacts / "start-guide-en.png"))
    el(driver, "guide-close").click()
    assert not shown(driver, "guide")
    # The tools dock's "?" opens the guide at the tool shown.
    el(driver, "dock-tab-tests").click()
    link = driver.find_element(By.CSS_SELECTOR, '.dock-bottom [data-testid="guide-link"]')
    assert link.get_attribute("data-section") == "tests"
    link.click()
    wait(driver, lambda: section_in_view(driver, "tests"), message="the tests section in view")
    Select(el(driver, "lang")).select_by_value("ja")
    wait(driver, lambda: guide_lang(driver) == "ja", message="the Japanese guide")
    wait(driver, lambda: section_in_view(driver, "tests"), message="still at the tests section")
    driver.save_screenshot(str(artifacts / "start-guide-ja.png"))
    driver.find_element(By.TAG_NAME, "body").send_keys(Keys.ESCAPE)
    wait(driver, lambda: not shown(driver, "guide"), message="Escape closes the guide")


def test_after_one_visit_the_guide_opens_offline(driver, artifacts):
    server = first_visit_kept_offline(driver)
    url = server.url
    el(driver, "help-guide").click()
    wait(driver, lambda: guide_lang(driver) == "en")
    Select(el(driver, "lang")).select_by_value("ja")
    wait(driver, lambda: guide_lang(driver) == "ja")
    server.stop()
    driver.get(url)
    wait(driver, lambda: el(driver, "ladder"), message="the page loads with the server gone")
    el(driver, "help-guide").click()
    wait(driver, lambda: guide_lang(driver) == "ja", message="the Japanese guide, offline")
    Select(el(driver, "lang")).select_by_value("en")
    wait(driver, lambda: guide_lang(driver) == "en", message="the English guide, offline")
    # The start screen is kept with the page too.
    el(driver, "help-start").click()
    wait(driver, lambda: shown(driver, "start-draw"), message="the start screen, offline")


@pytest.mark.first_visit
def test_an_exercise_opens_from_the_start_screen(driver, base_url):
    driver.get(base_url)
    wait(driver, lambda: shown(driver, "start-exercise"))
    el(driver, "start-exercise").click()
    wait(driver, lambda: shown(driver, "start-exercise-0"))
    el(driver, "start-exercise-0").click()
    wait(driver, lambda: el(driver, "dock-tab-tests", reveal=False).get_attribute("aria-selected") == "true",
         message="the exercise opens with its tests shown")
    wait(driver, lambda: "X02" in el(driver, "exercise-task").text, message="its task is shown")
    assert not shown(driver, "start")


@pytest.mark.first_visit
def test_open_a_file_from_the_start_screen_asks_for_the_file(driver, base_url):
    driver.get(base_url)
    wait(driver, lambda: shown(driver, "start-open"))
    # The browser's file chooser cannot be driven; the click that opens it
    # is caught instead.
    # The File menu's controls are drawn when the menu first opens (a part,
    # issue #53): the click is caught wherever the input is drawn.
    driver.execute_script(
        "document.addEventListener('click', (e) => { if (e.target.matches('[data-testid=open-file]'))"
        " { window.fileAsked = true; e.preventDefault(); } }, true);")
    el(driver, "start-open").click()
    wait(driver, lambda: driver.execute_script("return window.fileAsked === true"),
         message="the File menu's file input is asked for a file")
    assert not shown(driver, "start")
