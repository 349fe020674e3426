"""End-to-end: two tabs of the page on one profile (issue #26, "work is
never lost"): a tab with nothing unsaved follows the other's saves; a tab
whose save would overwrite work it has not seen shows the conflict."""

import json

from selenium.webdriver.common.keys import Keys

from test_app import el, open_fresh, wait
from test_ladder import focus_ladder, place, saved_ladder

KEY = "hashigo.ladder.minasec-u.v1"


def devices(driver, rung):
    """The devices drawn on row 0 of `rung`, left to right."""
    found = []
    for col in range(10):
        cells = driver.find_elements("css selector", f'[data-testid="cell-{rung}-0-{col}"]')
        if cells and cells[0].get_attribute("data-device"):
            found.append(cells[0].get_attribute("data-device"))
    return found


def drawn(ladder):
    """The rungs with something drawn (an output leaves an empty rung
    after it for the next)."""
    return [r for r in ladder["rungs"] if r["cells"]]


def save_from_a_tab_not_heard_of(driver, key, project):
    """Writes `project` under `key` with the next revision, as another tab
    would whose `storage` event this tab has not had yet (a tab does not
    hear of its own writes)."""
    driver.execute_script(
        "const rev = Number(localStorage.getItem(arguments[0] + '.rev') || '0');"
        "localStorage.setItem(arguments[0], arguments[1]);"
        "localStorage.setItem(arguments[0] + '.rev', String(rev + 1));",
        key, json.dumps(project))


def test_two_tabs_edit_one_ladder_and_nothing_is_lost(driver, base_url, artifacts):
    open_fresh(driver, base_url)
    tab_a = driver.current_window_handle
    driver.switch_to.new_window("tab")
    tab_b = driver.current_window_handle
    driver.get(base_url)
    wait(driver, lambda: el(driver, "mode-run"), message="tab B mounts")

    # B draws a rung; A, with nothing unsaved, follows it.
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    driver.switch_to.window(tab_a)
    wait(driver, lambda: devices(driver, 0) == ["X00", "Y00"], message="A shows B's rung")

    # A adds a rung below it: B's rung stays, and B follows A.
    focus_ladder(driver, "cell-1-0-0")
    place(driver, Keys.F5, "X01")
    place(driver, Keys.F7, "Y01")
    assert len(drawn(saved_ladder(driver, "minasec-u"))) == 2
    driver.switch_to.window(tab_b)
    wait(driver, lambda: devices(driver, 1) == ["X01", "Y01"], message="B shows A's rung")
    driver.refresh()
    wait(driver, lambda: el(driver, "mode-run"), message="B reloads")
    wait(driver, lambda: devices(driver, 0) == ["X00", "Y00"] and devices(driver, 1) == ["X01", "Y01"],
         message="a reload of B shows both tabs' work")
    assert not driver.find_elements("css selector", '[data-testid="storage-conflict"]')

    # Another tab saves while A has not heard of it; A's next edit would
    # overwrite it: the conflict is shown and nothing is written.
    driver.switch_to.window(tab_a)
    mine = json.loads(driver.execute_script("return localStorage.getItem(arguments[0])", KEY))
    theirs = json.loads(json.dumps(mine))
    theirs["ladder"]["rungs"] = theirs["ladder"]["rungs"][:1]
    save_from_a_tab_not_heard_of(driver, KEY, theirs)
    focus_ladder(driver, "cell-2-0-0")
    place(driver, Keys.F5, "X02")
    wait(driver, lambda: el(driver, "storage-conflict").is_displayed(), message="the conflict is shown")
    assert saved_ladder(driver, "minasec-u") == theirs["ladder"], "their work is not overwritten"
    driver.save_screenshot(str(artifacts / "storage-conflict.png"))

    # "Keep mine as a copy": a project of its own, opened here.
    el(driver, "conflict-keep-mine").click()
    wait(driver, lambda: "(this tab)" in el(driver, "notice").text, message="the copy is named")
    assert not driver.find_elements("css selector", '[data-testid="storage-conflict"]')
    index = json.loads(driver.execute_script("return localStorage.getItem('hashigo.projects.v1')"))["projects"]
    copy = [p for p in index if p["name"].endswith("(this tab)")]
    assert len(copy) == 1, index
    copy_key = f"hashigo.project.{copy[0]['id']}.v1"
    kept = json.loads(driver.execute_script("return localStorage.getItem(arguments[0])", copy_key))
    assert len(drawn(kept["ladder"])) == 3, "all of A's work is in the copy"
    assert saved_ladder(driver, "minasec-u") == theirs["ladder"], "theirs stays in its slot"

    # Another conflict on the copy; "Load theirs" shows their work, and the
    # next edit saves over it as usual.
    other = json.loads(json.dumps(kept))
    other["ladder"]["rungs"] = other["ladder"]["rungs"][:2]
    save_from_a_tab_not_heard_of(driver, copy_key, other)
    focus_ladder(driver, "cell-2-0-1")
    place(driver, Keys.F7, "Y02")
    wait(driver, lambda: el(driver, "storage-conflict").is_displayed(), message="the second conflict")
    el(driver, "conflict-load-theirs").click()
    wait(driver, lambda: devices(driver, 2) == [], message="their two rungs are shown")
    assert not driver.find_elements("css selector", '[data-testid="storage-conflict"]')
    focus_ladder(driver, "cell-2-0-0")
    place(driver, Keys.F5, "X03")
    place(driver, Keys.F7, "Y03")
    saved = json.loads(driver.execute_script("return localStorage.getItem(arguments[0])", copy_key))
    assert len(drawn(saved["ladder"])) == 3, "the edit after loading theirs is saved"
    assert not driver.find_elements("css selector", '[data-testid="storage-conflict"]')
