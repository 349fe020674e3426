"""End-to-end: the classroom (issue #49). An exercise made in the page
(a task, hidden tests, a hint) opened from its link in a fresh profile:
the task, Check my answer failing with the hint on the empty ladder and
passing once the student draws the answer; an older `2.` link; a clean
slate after an import; Share says Copied."""

import json
import subprocess

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import ROOT, el, open_fresh, wait
from test_ladder import HASHIGO, focus_ladder, place

NAMED = ROOT / "engine/tests/ladder/fixtures/openplc-named.xml"

# A `2.` exercise link made by `hashigo share` before exercises had a task
# (commit 4f69933): an empty MINASEC-U ladder, the case "X00 lights Y00"
# (0ms,X00,1 / Y00 = 1 at 100ms), "exercise": true. Also a fixture of
# engine/tests/ladder/exercise.rs.
OLD_LINK = "2.ATIAzf8AAAAAAQEOWDAwIGxpZ2h0cyBZMDAKMG1zLFgwMCwxCgEQWTAwID0gMSBhdCAxMDBtcw"

TASK = "Light **Y00** while X00 is on.\n\n- one contact\n- one coil"
HINT = "Y00 must follow X00: one contact, one coil."


def found(driver, testid):
    return driver.find_elements(By.CSS_SELECTOR, f'[data-testid="{testid}"]')


def result(driver):
    r = el(driver, "exercise-result")
    return r.get_attribute("data-passed"), r.get_attribute("data-total")


def make_exercise(driver, base_url):
    """The teacher's exercise on the IO86A: a task, one hidden case with a
    hint, an empty ladder; its share link."""
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("io86a")
    wait(driver, lambda: el(driver, "palette"))
    el(driver, "new-ladder").click()
    el(driver, "tests-open").click()
    wait(driver, lambda: el(driver, "add-test")).click()
    case = wait(driver, lambda: el(driver, "test-case-0"))
    # The boxes show the syntax while they are empty.
    events = case.find_element(By.CSS_SELECTOR, '[data-testid="test-events"]')
    assert "0.1s,X00,1" in events.get_attribute("placeholder")
    name = case.find_element(By.CSS_SELECTOR, '[data-testid="test-name"]')
    name.clear()
    name.send_keys("X00 lights Y00", Keys.TAB)
    events.send_keys("0ms,X00,1\n")
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]').send_keys("Y00 = 1 at 100ms")
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-hint"]').send_keys(HINT, Keys.TAB)
    el(driver, "exercise").click()
    task = wait(driver, lambda: el(driver, "exercise-task-edit"))
    task.send_keys(TASK)
    el(driver, "exercise-tests-hidden").click()
    wait(driver, lambda: el(driver, "exercise-tests-hidden").is_selected())
    el(driver, "share").click()
    wait(driver, lambda: el(driver, "share-copied").text, message="Share says the link was copied")
    assert el(driver, "share-copied").get_attribute("data-copied") == "true", el(driver, "share-copied").text
    assert el(driver, "share-copied").text == "Link copied"
    link = el(driver, "share-url").get_attribute("value")
    assert "#4." in link, link
    return link


def test_an_exercise_made_in_the_page_is_checked_in_a_fresh_profile(driver, base_url, artifacts):
    link = make_exercise(driver, base_url)
    # The student: a fresh profile, the link.
    open_fresh(driver, base_url)
    driver.get(link)
    task = wait(driver, lambda: el(driver, "exercise-task"), message="the task is shown")
    assert "Light Y00 while X00 is on." in task.text
    assert task.find_element(By.CSS_SELECTOR, "strong").text == "Y00"
    assert [li.text for li in task.find_elements(By.CSS_SELECTOR, "li")] == ["one contact", "one coil"]
    # Nothing to keep or leave: the profile had no work of its own.
    assert not found(driver, "shared-banner")
    # The hidden tests are not shown, and nothing edits or deletes them.
    assert not found(driver, "test-case-0")
    for testid in ["add-test", "test-delete", "run-tests", "exercise-task-edit", "record-test"]:
        assert not found(driver, testid), testid
    assert "answer: 1 (hidden" in el(driver, "tests-hidden-note").text
    # The empty ladder fails, in the student's words: the case and its hint.
    el(driver, "exercise-check").click()
    wait(driver, lambda: found(driver, "exercise-result"))
    assert result(driver) == ("0", "1")
    said = el(driver, "exercise-result").text
    assert "X00 lights Y00" in said and HINT in said, said
    assert "expectation" not in said and "events line" not in said, said
    assert "fail" in el(driver, "exercise-result").get_attribute("class")
    driver.set_window_size(1366, 768)
    driver.save_screenshot(str(artifacts / "classroom-student-fail-1366.png"))
    # The student draws the answer.
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    el(driver, "exercise-check").click()
    wait(driver, lambda: result(driver) == ("1", "1"), message=el(driver, "exercise-result").text)
    assert "pass" in el(driver, "exercise-result").get_attribute("class")
    driver.save_screenshot(str(artifacts / "classroom-student-pass-1366.png"))
    # The answer goes back as a link the teacher opens, checked at once.
    el(driver, "exercise-send").click()
    answer = el(driver, "exercise-answer-url").get_attribute("value")
    assert "?answer#4." in answer, answer
    # An edit after sending takes the link away: it holds the ladder as
    # it was, which the student no longer has.
    focus_ladder(driver)
    driver.switch_to.active_element.send_keys(Keys.CONTROL, "z")
    wait(driver, lambda: not found(driver, "exercise-answer-url"), message="the old answer link is gone")
    open_fresh(driver, base_url)
    driver.get(answer)
    wait(driver, lambda: found(driver, "exercise-result") and result(driver) == ("1", "1"),
         message="the teacher sees the answer's result")


def test_an_older_two_dot_exercise_link_still_opens(driver, base_url):
    open_fresh(driver, base_url)
    driver.get(f"{base_url}/#{OLD_LINK}")
    case = wait(driver, lambda: el(driver, "test-case-0"), message="the tests are shown")
    assert not found(driver, "shared-banner")
    # Shown, not editable.
    for box in ["test-events", "test-expect", "test-name"]:
        assert case.find_element(By.CSS_SELECTOR, f'[data-testid="{box}"]').get_attribute("readonly")
    assert not found(driver, "test-delete")
    el(driver, "exercise-check").click()
    wait(driver, lambda: found(driver, "exercise-result"))
    assert result(driver) == ("0", "1")
    assert "does not pass yet" in el(driver, "exercise-result").text


def test_importing_after_an_exercise_leaves_no_old_result(driver, base_url):
    link = make_exercise(driver, base_url)
    el(driver, "exercise-student-view").click()
    el(driver, "exercise-check").click()
    wait(driver, lambda: found(driver, "exercise-result"))
    el(driver, "exercise-edit").click()
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "fail")
    assert el(driver, "tests-summary").text.startswith("0 / 1")
    el(driver, "open-file").send_keys(str(NAMED))
    wait(driver, lambda: el(driver, "import-dialog"))
    memo = el(driver, "import-map-memo")
    memo.clear()
    memo.send_keys("M05")
    el(driver, "import-apply").click()
    wait(driver, lambda: not found(driver, "import-dialog"))
    assert el(driver, "tests-summary").text == ""
    assert el(driver, "test-case-0").get_attribute("data-result") == ""
    assert not found(driver, "exercise-result")
    assert link


@pytest.mark.parametrize("name", ["laptop", "phone"])
def test_the_students_view_on_a_laptop_and_a_phone(tmp_path, base_url, artifacts, name):
    from test_screens import no_sideways_overflow, screen_driver

    project = tmp_path / "exercise.json"
    project.write_text(json.dumps({
        "format": "hashigo-project", "version": 3, "machine": "minasec-u",
        "ladder": {"rungs": []},
        "tests": [{"name": "X00 lights Y00", "events": "0ms,X00,1\n",
                   "expect": ["Y00 = 1 at 100ms"], "hint": HINT}],
        "exercise": {"task": {"en": TASK, "ja": "X00 が入っている間 **Y00** を点ける。"},
                     "tests": "hidden"},
    }))
    fragment = subprocess.run([str(HASHIGO), "share", "--program", str(project)], check=True,
                              capture_output=True, text=True).stdout.strip()
    assert fragment.startswith("4."), fragment
    driver = screen_driver(tmp_path, name)
    try:
        open_fresh(driver, base_url)
        driver.get(f"{base_url}/#{fragment}")
        wait(driver, lambda: el(driver, "exercise-task"), message="the task is shown")
        el(driver, "exercise-check").click()
        wait(driver, lambda: found(driver, "exercise-result"))
        assert result(driver) == ("0", "1")
        driver.execute_script(
            "document.querySelector('[data-testid=exercise-result]').scrollIntoView({block: 'end'})")
        assert no_sideways_overflow(driver)
        driver.save_screenshot(str(artifacts / f"classroom-student-{name}.png"))
    finally:
        driver.quit()
