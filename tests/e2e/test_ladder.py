"""End-to-end: the ladder editor (issue #13) in headless Chromium."""

import base64
import json
import zlib
import re
import time
import subprocess

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from conftest import record_figures
from test_app import ROOT, el, on, open_fresh, severe_console_messages, wait

HASHIGO = ROOT / "target" / "release" / "hashigo"


def keys(driver, *k):
    """Types into whatever has the focus (the ladder, or the device entry)."""
    driver.switch_to.active_element.send_keys(*k)


def focus_ladder(driver, cell="cell-0-0-0"):
    el(driver, cell).click()
    assert driver.switch_to.active_element.get_attribute("data-testid") == "ladder"


def place(driver, key, device, shift=False):
    """F5/F6/F7/F8 (with Shift for an OR branch), the device, Enter."""
    if shift:
        ActionChains(driver).key_down(Keys.SHIFT).send_keys(key).key_up(Keys.SHIFT).perform()
    else:
        keys(driver, key)
    assert driver.switch_to.active_element.get_attribute("data-testid") == "device-input"
    keys(driver, device, Keys.ENTER)
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "ladder",
         message=f"{device} placed, focus back on the ladder")


def saved_ladder(driver, machine):
    raw = driver.execute_script("return localStorage.getItem(arguments[0])", f"hashigo.ladder.{machine}.v1")
    return json.loads(raw)["ladder"] if raw else None


def steps(listing):
    """The instruction lines of a listing, without comments."""
    return [l for l in listing.splitlines() if l.strip() and not l.startswith(";")]


def cursor(driver):
    return driver.find_element(By.CSS_SELECTOR, '[data-testid="ladder"] [aria-selected="true"]').get_attribute("data-testid")


def test_draw_the_seed_program_with_the_keyboard_and_run_it(driver, base_url, artifacts):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    # Rung 0: X00, /X01, (Y00), and Y00 in parallel with X00.
    place(driver, Keys.F5, "X00")
    assert cursor(driver) == "cell-0-0-1", "after a contact the cursor moves right"
    place(driver, Keys.F6, "X01")
    place(driver, Keys.F7, "Y00")
    assert cursor(driver) == "cell-1-0-0", "after an output: the next rung, created"
    keys(driver, Keys.ARROW_UP)
    assert cursor(driver) == "cell-0-1-0"
    place(driver, Keys.F5, "Y00", shift=True)
    keys(driver, Keys.ARROW_DOWN, Keys.ARROW_DOWN, Keys.HOME)
    assert cursor(driver) == "cell-1-0-0"
    # Rung 1: Y00, /T1, (T0).
    place(driver, Keys.F5, "Y00")
    place(driver, Keys.F6, "T1")
    place(driver, Keys.F7, "T0")
    # Rung 2: T0, (T1) and (C0) in parallel.
    place(driver, Keys.F5, "T0")
    place(driver, Keys.F7, "T1")
    keys(driver, Keys.ARROW_UP, Keys.END)
    assert cursor(driver) == "cell-2-1-9"
    place(driver, Keys.F7, "C0")
    assert cursor(driver) == "cell-2-2-0", "after an output on a lower row: the next row"
    keys(driver, Keys.ARROW_UP, Keys.ARROW_UP, Keys.END)
    ActionChains(driver).key_down(Keys.SHIFT).send_keys(Keys.F9).key_up(Keys.SHIFT).perform()
    keys(driver, Keys.ARROW_DOWN, Keys.ARROW_DOWN, Keys.ARROW_DOWN, Keys.HOME)
    assert cursor(driver) == "cell-3-0-0"
    # Rung 3: C0, (Y01). Rung 4: X02, (C0R).
    place(driver, Keys.F5, "C0")
    place(driver, Keys.F7, "Y01")
    place(driver, Keys.F5, "X02")
    place(driver, Keys.F7, "C0R")

    cell = el(driver, "cell-0-0-0")
    assert (cell.get_attribute("data-kind"), cell.get_attribute("data-device")) == ("no", "X00")
    assert el(driver, "cell-0-0-1").get_attribute("data-kind") == "nc"
    assert el(driver, "cell-0-1-0").get_attribute("data-kind") == "no"
    assert el(driver, "cell-2-1-9").get_attribute("data-kind") == "coil"
    assert el(driver, "cell-0-0-4").get_attribute("data-kind") == "hwire"
    assert "rung 1, row 1, column 1: normally open contact X00" in cell.get_attribute("aria-label")
    assert el(driver, "problems").text.strip() == "No problems."
    assert el(driver, "rung-2").get_attribute("data-first-step") == "7"

    # The listing is the seed's program, step for step.
    seed = subprocess.run(
        [str(HASHIGO), "compile", "--program", str(ROOT / "engine/programs/minasec-u/seed-test.json")],
        check=True, capture_output=True, text=True,
    ).stdout
    assert steps(el(driver, "il-listing").text) == steps(seed)
    driver.save_screenshot(str(artifacts / "ladder-seed.png"))

    # Write it to the board and run it.
    el(driver, "ladder-write").click()
    wait(driver, lambda: "ST   C0R" in el(driver, "program-text").get_attribute("value"))
    el(driver, "counter-set-ones").send_keys(Keys.ARROW_UP, Keys.ARROW_UP, Keys.ARROW_UP)
    wait(driver, lambda: el(driver, "counter-set-ones").get_attribute("aria-valuenow") == "3")
    Select(el(driver, "speed")).select_by_value("max")
    el(driver, "mode-run").click()
    el(driver, "input-X00").click()
    wait(driver, lambda: on(driver, "lamp-Y00"), message="Y00 latches on")
    el(driver, "input-X00").click()
    wait(driver, lambda: el(driver, "seg7").text == "03" and on(driver, "lamp-Y01"), timeout=60,
         message="the count climbs to the preset and Y01 lights")
    assert severe_console_messages(driver) == []

    # Reloading brings the ladder back.
    driver.refresh()
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")


def test_an_io86a_orb_rung_drawn_with_the_mouse_and_palette(driver, base_url):
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("io86a")
    wait(driver, lambda: el(driver, "palette"))
    # What IO86A lacks is shown disabled, with the reason.
    ton = el(driver, "palette-ton")
    assert ton.get_attribute("aria-disabled") == "true"
    assert "has no in-line timers" in ton.get_attribute("data-reason")
    assert el(driver, "palette-mov").get_attribute("aria-disabled") == "false"

    def drop(item, cell):
        driver.execute_script(
            """const dt = new DataTransfer(); dt.setData('text/plain', 'palette:' + arguments[0]);
               arguments[1].dispatchEvent(new DragEvent('drop', {dataTransfer: dt, bubbles: true, cancelable: true}));""",
            item, el(driver, cell))

    def entry(device):
        wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "device-input")
        keys(driver, device, Keys.ENTER)
        wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "ladder")

    # The workspace opened with device A's program as a ladder; start anew.
    assert el(driver, "cell-0-0-0").get_attribute("data-kind") != ""
    el(driver, "new-ladder").click()
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-kind") == "")
    el(driver, "cell-0-0-0").click()
    el(driver, "palette-no").click(); entry("X00")
    el(driver, "palette-no").click(); entry("X01")
    el(driver, "palette-coil").click(); entry("Y00")
    el(driver, "cell-0-1-0").click()
    drop("no", "cell-0-1-0"); entry("X02")      # dragged from the palette
    el(driver, "palette-no").click(); entry("X03")
    el(driver, "cell-0-0-2").click()
    el(driver, "palette-link").click()
    assert "link-down" in el(driver, "cell-0-0-2").get_attribute("class")
    wait(driver, lambda: "ORB" in el(driver, "il-listing").text)
    assert steps(el(driver, "il-listing").text) == [
        "LD X00", "AND X01", "LD X02", "AND X03", "ORB", "OUT Y00", "END",
    ]
    # Double-click edits a cell.
    ActionChains(driver).double_click(el(driver, "cell-0-1-1")).perform()
    wait(driver, lambda: el(driver, "device-input").get_attribute("value") == "X03")
    keys(driver, Keys.BACKSPACE, "4", Keys.ENTER)
    wait(driver, lambda: el(driver, "cell-0-1-1").get_attribute("data-device") == "X04")


def test_fifty_edits_undone_and_redone_restore_the_exact_ladder(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    edits = 0
    for rung in range(5):
        for col in range(4):
            place(driver, Keys.F5 if col % 2 == 0 else Keys.F6, f"X0{(rung + col) % 8}")
            edits += 1
        place(driver, Keys.F7, f"Y0{rung}")
        edits += 1
    # Five rungs of 4 contacts and a coil: 25 edits; the rest are wires,
    # branches, comments, moves and deletions.
    for rung in range(5):
        el(driver, f"cell-{rung}-0-8").click()
        keys(driver, Keys.DELETE)  # the wire before the coil
        keys(driver, Keys.F9)      # and back
        edits += 2
    while edits < 50:
        keys(driver, Keys.INSERT)
        edits += 1
    final = saved_ladder(driver, "minasec-u")
    assert final and len(final["rungs"]) > 5
    for _ in range(edits):
        ActionChains(driver).key_down(Keys.CONTROL).send_keys("z").key_up(Keys.CONTROL).perform()
    wait(driver, lambda: saved_ladder(driver, "minasec-u") == {"rungs": []}, message="all undone")
    assert el(driver, "undo").get_attribute("disabled") is not None
    for _ in range(edits):
        ActionChains(driver).key_down(Keys.CONTROL).send_keys("y").key_up(Keys.CONTROL).perform()
    wait(driver, lambda: saved_ladder(driver, "minasec-u") == final, message="all redone")
    assert el(driver, "redo").get_attribute("disabled") is not None


def test_a_device_the_machine_lacks_is_refused_at_entry(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    keys(driver, Keys.F5)
    keys(driver, "X09", Keys.ENTER)
    wait(driver, lambda: el(driver, "device-error").text != "")
    assert "X09" in el(driver, "device-error").text
    assert driver.switch_to.active_element.get_attribute("data-testid") == "device-input"
    assert el(driver, "cell-0-0-0").get_attribute("data-kind") == ""
    assert saved_ladder(driver, "minasec-u") is None, "nothing changed, nothing saved"
    keys(driver, Keys.ESCAPE)
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "ladder")
    # Completion offers the machine's devices with their comments.
    keys(driver, Keys.F5)
    keys(driver, "X0")
    options = el(driver, "device-options").text
    assert "X00" in options and "X07" in options and "Y00" not in options


def test_errors_mark_their_cells_and_a_problem_moves_the_cursor(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    # A contact on the free row, joined to nothing: dangling.
    el(driver, "cell-0-1-2").click()
    place(driver, Keys.F5, "X01")
    wait(driver, lambda: el(driver, "cell-0-1-2").get_attribute("data-error"))
    assert "dangling" in el(driver, "cell-0-1-2").get_attribute("data-error")
    assert el(driver, "cell-0-0-0").get_attribute("data-error") is None
    assert el(driver, "il-listing-none")
    assert el(driver, "ladder-write").get_attribute("disabled") is not None
    # Saved although it does not compile.
    assert saved_ladder(driver, "minasec-u")["rungs"][0]["cells"][1][2]["device"] == "X01"
    keys(driver, Keys.HOME, Keys.ARROW_UP)
    driver.find_element(By.CSS_SELECTOR, '[data-testid="problems"] .problem').click()
    assert cursor(driver) == "cell-0-1-2"
    assert driver.switch_to.active_element.get_attribute("data-testid") == "ladder"
    # Linking it in parallel with X00 fixes it.
    keys(driver, Keys.DELETE)
    el(driver, "cell-0-1-0").click()
    place(driver, Keys.F5, "X01", shift=True)
    wait(driver, lambda: el(driver, "problems").text.strip() == "No problems.")
    assert steps(el(driver, "il-listing").text)[:3] == ["000 LD   X00", "001 OR   X01", "002 ST   Y00"]


def test_copy_and_paste_rungs_and_load_text_as_ladder(driver, base_url):
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("io86a")
    text = el(driver, "io86a-program-text")
    text.clear()
    text.send_keys("LD X00\nOR Y00\nANI X01\nOUT Y00\nLD X02\nOUT Y01\nEND\n")
    el(driver, "load-as-ladder").click()
    wait(driver, lambda: el(driver, "cell-1-0-0").get_attribute("data-device") == "X02")
    assert el(driver, "cell-0-1-0").get_attribute("data-device") == "Y00"
    # Select rung 0 and 1 (Shift+Down into the next rung), copy, paste at the end.
    focus_ladder(driver)
    ActionChains(driver).key_down(Keys.SHIFT).send_keys(Keys.DOWN, Keys.DOWN, Keys.DOWN).key_up(Keys.SHIFT).perform()
    ActionChains(driver).key_down(Keys.CONTROL).send_keys("c").key_up(Keys.CONTROL).perform()
    ActionChains(driver).key_down(Keys.CONTROL).send_keys(Keys.END).key_up(Keys.CONTROL).perform()
    ActionChains(driver).key_down(Keys.CONTROL).send_keys("v").key_up(Keys.CONTROL).perform()
    wait(driver, lambda: len(driver.find_elements(By.CSS_SELECTOR, '.ladder .rung:not(.end)')) == 4,
         message="two rungs pasted")
    assert el(driver, "cell-3-0-0").get_attribute("data-device") == "X02"
    # The whole ladder goes to MINASEC-U, whose devices it happens to use.
    Select(el(driver, "copy-to")).select_by_value("minasec-u")
    wait(driver, lambda: el(driver, "machine").get_attribute("value") == "minasec-u")
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-device") == "X00")
    assert el(driver, "problems").text.strip() == "No problems."


def test_find_cross_reference_and_batch_replace(driver, base_url):
    open_fresh(driver, base_url)
    Select(el(driver, "example")).select_by_value("seed-test")
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R",
         message="the example opens as a ladder")
    # A device comment shows under the device in every cell that uses it.
    el(driver, "cell-1-0-0").click()  # Y00's contact
    el(driver, "device-comment-input").send_keys("running", Keys.ENTER)
    wait(driver, lambda: "running" in el(driver, "cell-0-0-9").text)
    assert "running" in el(driver, "cell-0-1-0").text and "running" in el(driver, "cell-1-0-0").text
    assert "running" in el(driver, "cell-1-0-0").get_attribute("aria-label")
    el(driver, "rung-comment-input").send_keys("flicker", Keys.ENTER)
    wait(driver, lambda: "flicker" in el(driver, "rung-1").text)
    focus_ladder(driver, "cell-3-0-0")
    ActionChains(driver).key_down(Keys.CONTROL).send_keys("f").key_up(Keys.CONTROL).perform()
    find = el(driver, "find")
    find.send_keys("Y00")
    wait(driver, lambda: len(el(driver, "xref").find_elements(By.TAG_NAME, "tr")) == 3)
    rows = [r.text for r in el(driver, "xref").find_elements(By.TAG_NAME, "tr")]
    assert [r.split()[0] for r in rows] == ["coil", "contact", "contact"]
    assert "step 4" in rows[2], rows
    el(driver, "xref").find_elements(By.TAG_NAME, "button")[2].click()
    assert cursor(driver) == "cell-1-0-0"
    # Selecting a rung lights its steps in the listing; a step shows its rung.
    el(driver, "il-listing")  # the Listing tab shown
    lit = [s.get_attribute("data-step") for s in driver.find_elements(By.CSS_SELECTOR, '.listing .lit')]
    assert lit == ["4", "5", "6"]
    driver.find_element(By.CSS_SELECTOR, '.listing [data-step="12"]').click()
    assert cursor(driver) == "cell-4-0-0"
    # Batch replace with a preview.
    el(driver, "replace-from").send_keys("X00")
    el(driver, "replace-to").send_keys("X03")
    wait(driver, lambda: "contact X00 → contact X03" in el(driver, "replace-preview").text)
    el(driver, "replace-apply").click()
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-device") == "X03")
    # The key map.
    focus_ladder(driver, "cell-0-0-0")
    keys(driver, "?")
    assert "F5" in el(driver, "keymap").text
    keys(driver, Keys.ESCAPE)
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="keymap"]'))


def test_a_clip_from_another_tab_pastes_through_the_clipboard(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    clip = ('hashigo-clip 1\n{"kind":"rungs","rungs":[{"comment":"from the other tab","cells":'
            '[[{"type":"contact","kind":"no","device":"X05"},{"type":"coil","kind":"normal","device":"Y05"}]]}]}\n')
    paste = """const dt = new DataTransfer(); dt.setData('text/plain', arguments[0]);
               document.activeElement.dispatchEvent(new ClipboardEvent('paste', {clipboardData: dt, bubbles: true, cancelable: true}));"""
    driver.execute_script(paste, clip)
    wait(driver, lambda: el(driver, "cell-0-0-1").get_attribute("data-device") == "Y05")
    assert "from the other tab" in el(driver, "rung-0").text
    # What the machine lacks is refused, all of it.
    driver.execute_script(paste, clip.replace("X05", "X09"))
    wait(driver, lambda: "X09" in el(driver, "edit-message").text)
    assert len(driver.find_elements(By.CSS_SELECTOR, ".ladder .rung:not(.end)")) == 1
    # Ctrl+C puts the same text form on the system clipboard's event.
    driver.execute_script("""window.copied = null;
        window.addEventListener('copy', e => { window.copied = e.clipboardData.getData('text/plain'); });""")
    focus_ladder(driver)
    ActionChains(driver).key_down(Keys.CONTROL).send_keys("c").key_up(Keys.CONTROL).perform()
    wait(driver, lambda: driver.execute_script("return window.copied"), message="a copy event")
    copied = driver.execute_script("return window.copied")
    assert copied.startswith("hashigo-clip 1\n") and "X05" in copied


def test_a_saved_ladder_that_does_not_read_is_kept_aside(driver, base_url):
    open_fresh(driver, base_url)
    driver.execute_script("localStorage.setItem('hashigo.ladder.minasec-u.v1', '{\"format\": \"nope\"}')")
    driver.refresh()
    wait(driver, lambda: "hashigo.ladder.minasec-u.v1.corrupt." in el(driver, "notice").text)
    kept = driver.execute_script(
        "return Object.keys(localStorage).filter(k => k.startsWith('hashigo.ladder.minasec-u.v1.corrupt.'))")
    assert len(kept) == 1
    assert driver.execute_script("return localStorage.getItem(arguments[0])", kept[0]) == '{"format": "nope"}'


def test_share_a_ladder_and_open_the_link_without_losing_your_own(driver, base_url):
    open_fresh(driver, base_url)
    Select(el(driver, "example")).select_by_value("seed-test")
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")
    el(driver, "share").click()
    link = el(driver, "share-url").get_attribute("value")
    assert link.startswith(base_url + "/#1.") or link.startswith(base_url + "/#2."), link
    shared = saved_ladder(driver, "minasec-u")
    # The CLI reads the same link back into the same ladder.
    project = json.loads(subprocess.run([str(HASHIGO), "unshare", link], check=True,
                                        capture_output=True, text=True).stdout)
    assert project["machine"] == "minasec-u" and project["ladder"] == shared
    assert project["settings"]["C0"] == "10"

    # Someone else, with work of their own.
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X07")
    place(driver, Keys.F7, "Y07")
    own = saved_ladder(driver, "minasec-u")
    driver.get(link)
    wait(driver, lambda: el(driver, "shared-banner"), message="the banner")
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")
    assert saved_ladder(driver, "minasec-u") == own, "opening a link saves nothing"
    # Back: their own ladder, untouched.
    el(driver, "shared-back").click()
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-device") == "X07")
    assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="shared-banner"]')
    assert saved_ladder(driver, "minasec-u") == own
    # Open it again and keep it: it becomes a project of its own; their
    # own ladder stays saved where it was.
    driver.get(link)
    wait(driver, lambda: el(driver, "shared-banner"))
    el(driver, "shared-keep").click()
    wait(driver, lambda: "Kept as the project" in el(driver, "notice").text)
    index = json.loads(driver.execute_script("return localStorage.getItem('hashigo.projects.v1')"))
    [entry] = index["projects"]
    kept = json.loads(driver.execute_script("return localStorage.getItem(arguments[0])",
                                            f"hashigo.project.{entry['id']}.v1"))
    assert kept["ladder"] == shared and entry["machine"] == "minasec-u"
    assert saved_ladder(driver, "minasec-u") == own
    assert el(driver, "counter-set-tens").get_attribute("aria-valuenow") == "1", "settings came too"
    # A reload shows the kept project; their own ladder is one click away.
    driver.get(base_url)
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")
    el(driver, "projects-open").click()
    assert entry["name"] in el(driver, "project-open-name").text


def test_a_broken_link_changes_nothing(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X07")
    place(driver, Keys.F7, "Y07")
    own = saved_ladder(driver, "minasec-u")
    # A 1.2 KB link that unpacks into 300 000 empty rungs (issue #24).
    packer = zlib.compressobj(9, zlib.DEFLATED, -15)
    count = 300_000
    varint = bytes([count & 0x7F | 0x80, (count >> 7) & 0x7F | 0x80, count >> 14])
    packed = packer.compress(bytes([1, 0, 0]) + varint + b"\0\0\0" * count) + packer.flush()
    many = "1." + base64.urlsafe_b64encode(packed).decode().rstrip("=")
    for fragment, says in [("1.AAAA", ""), ("9.xyz", ""), ("1." + "A" * 70000, "65536"),
                           (many, "holds 300000 rungs, more than the 10000")]:
        driver.get(f"{base_url}/#{fragment}")
        wait(driver, lambda: "does not hold a ladder" in el(driver, "notice").text)
        assert says in el(driver, "notice").text
        assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="shared-banner"]')
        assert el(driver, "cell-0-0-0").get_attribute("data-device") == "X07"
        assert saved_ladder(driver, "minasec-u") == own


def one_rung_link(machine, contact, coil):
    """The share fragment (from `hashigo share`) of a project on `machine`
    with one rung: `contact` -> (`coil`)."""
    project = ROOT / f"tests/e2e/artifacts/{machine}-project.json"
    project.parent.mkdir(exist_ok=True)
    project.write_text(json.dumps({
        "format": "hashigo-project", "version": 1, "machine": machine,
        "ladder": {"rungs": [{"cells": [[{"type": "contact", "kind": "no", "device": contact},
                                         {"type": "coil", "kind": "normal", "device": coil}]]}]},
    }))
    return subprocess.run([str(HASHIGO), "share", "--program", str(project)], check=True,
                          capture_output=True, text=True).stdout.strip()


def test_an_io86a_link_opens_on_the_io86a(driver, base_url):
    fragment = one_rung_link("io86a", "X03", "Y02")
    open_fresh(driver, base_url)
    driver.get(f"{base_url}/#{fragment}")
    wait(driver, lambda: el(driver, "machine").get_attribute("value") == "io86a")
    wait(driver, lambda: el(driver, "cell-0-0-1").get_attribute("data-device") == "Y02")
    assert el(driver, "shared-banner")


CAPTURE = """
window.downloads = [];
HTMLAnchorElement.prototype.click = function () {
  const name = this.download, href = this.href;
  fetch(href).then(r => href.startsWith('data:image/png') ? r.arrayBuffer().then(b => b.byteLength)
                                                         : r.text())
    .then(body => window.downloads.push({name, body}));
};
"""


def downloads(driver, n):
    wait(driver, lambda: len(driver.execute_script("return window.downloads")) >= n, message="downloads")
    return {d["name"]: d["body"] for d in driver.execute_script("return window.downloads")}


def test_files_save_open_and_pictures(driver, base_url, tmp_path):
    open_fresh(driver, base_url)
    Select(el(driver, "example")).select_by_value("seed-test")
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")
    el(driver, "cell-0-0-0").click()
    el(driver, "device-comment-input").send_keys("<b>start</b> & go", Keys.ENTER)
    wait(driver, lambda: "<b>start</b>" in el(driver, "cell-0-0-0").text, message="comments are text")
    driver.execute_script(CAPTURE)
    for button in ["save-json", "export-plcopen", "export-text", "export-svg", "export-png"]:
        el(driver, button).click()
    got = downloads(driver, 5)
    project = json.loads(got["minasec-u-ladder.json"])
    assert project["ladder"] == saved_ladder(driver, "minasec-u")
    assert "<project" in got["minasec-u-ladder.xml"] and "X00" in got["minasec-u-ladder.xml"]
    assert steps(got["minasec-u-ladder.txt"]) == steps(el(driver, "il-listing").text)
    svg = got["minasec-u-ladder.svg"]
    assert svg.startswith("<svg") and "&lt;b&gt;start&lt;/b&gt; &amp; go" in svg and "<b>" not in svg
    assert ">C0R<" in svg
    assert got["minasec-u-ladder.png"] > 1000, "a PNG of some size"

    # The saved project opens again (after a new ladder), one undo away.
    saved = tmp_path / "mine.json"
    saved.write_text(got["minasec-u-ladder.json"])
    el(driver, "new-ladder").click()
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-kind") == "")
    el(driver, "open-file").send_keys(str(saved))
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")
    assert saved_ladder(driver, "minasec-u") == project["ladder"], "JSON out and in: the same project"
    listing = steps(el(driver, "il-listing").text)
    # A bad file is refused at its line; nothing changes.
    bad = tmp_path / "bad.json"
    bad.write_text('{\n  "format": "hashigo-project",\n  "version": 99,\n  "machine": "minasec-u",\n  "ladder": {"rungs": []}\n}\n')
    el(driver, "open-file").send_keys(str(bad))
    wait(driver, lambda: "bad.json:3:" in el(driver, "edit-message").text)
    assert el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R"
    # The exported PLCopen file opens too.
    xml = tmp_path / "main.xml"
    xml.write_text(got["minasec-u-ladder.xml"])
    el(driver, "new-ladder").click()
    el(driver, "open-file").send_keys(str(xml))
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")
    assert steps(el(driver, "il-listing").text) == listing, "PLCopen out and in: the same program"
    opened = saved_ladder(driver, "minasec-u")
    assert [r.get("comment", "") for r in opened["rungs"]] == [r.get("comment", "") for r in project["ladder"]["rungs"]]


def test_the_page_runs_under_a_csp_with_no_inline_script(driver, base_url):
    open_fresh(driver, base_url)
    assert driver.execute_script("return document.querySelectorAll('script:not([src])').length") == 0
    csp = driver.execute_script(
        "return document.querySelector('meta[http-equiv=\"Content-Security-Policy\"]').content")
    assert "script-src 'self' 'wasm-unsafe-eval'" in csp and "unsafe-inline" not in csp.split("script-src")[1].split(";")[0]
    # An inline script injected now is refused by the policy.
    driver.execute_script("""const s = document.createElement('script'); s.textContent = 'window.ran = 1';
                             document.body.appendChild(s);""")
    assert driver.execute_script("return window.ran === undefined")
    assert el(driver, "ladder")


def first_visit_kept_offline(driver):
    """A server of its own for dist/, the page visited until the service
    worker controls it; returns the server (stop it to be offline)."""
    from conftest import DistServer

    server = DistServer()
    driver.get(server.url)
    wait(driver, lambda: el(driver, "ladder"))
    wait(driver, lambda: driver.execute_script("return navigator.serviceWorker.controller !== null"),
         timeout=30, message="the worker controls the page")
    return server


def test_after_the_first_visit_the_page_works_offline(driver, artifacts):
    server = first_visit_kept_offline(driver)
    url = server.url
    manifest = driver.execute_script("return document.querySelector('link[rel=manifest]').href")
    assert manifest.endswith("manifest.webmanifest")
    server.stop()
    driver.get(url)
    wait(driver, lambda: el(driver, "ladder"), message="the page loads with the server gone")
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    assert "ST   Y00" in el(driver, "il-listing").text
    # The files worker, never used online, was kept too (issue #29).
    el(driver, "open-file").send_keys(str(ROOT / "engine/tests/ladder/fixtures/openplc-named.xml"))
    wait(driver, lambda: el(driver, "import-dialog"), message="PLCopen import works offline")


def test_projects_new_open_rename_duplicate_delete(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X01")
    place(driver, Keys.F7, "Y01")
    own = saved_ladder(driver, "minasec-u")
    el(driver, "projects-open").click()
    el(driver, "project-name").send_keys("Pump")
    el(driver, "project-new").click()
    wait(driver, lambda: el(driver, "project-open-name").text == "Pump")
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-kind") == "")
    focus_ladder(driver)
    place(driver, Keys.F5, "X02")
    place(driver, Keys.F7, "Y02")
    index = lambda: json.loads(driver.execute_script("return localStorage.getItem('hashigo.projects.v1')"))["projects"]
    pump = index()[0]
    saved = lambda pid: json.loads(driver.execute_script(
        "return localStorage.getItem(arguments[0])", f"hashigo.project.{pid}.v1"))["ladder"]
    wait(driver, lambda: saved(pump["id"])["rungs"][0]["cells"][0][0]["device"] == "X02")
    assert saved_ladder(driver, "minasec-u") == own, "the machine's own ladder is untouched"
    # Duplicate, rename the copy, open it.
    el(driver, "project-Pump").find_element(By.CSS_SELECTOR, '[data-testid="project-duplicate"]').click()
    wait(driver, lambda: len(index()) == 2)
    el(driver, "project-name").send_keys("Fan")
    el(driver, "project-Pump (copy)").find_element(By.CSS_SELECTOR, '[data-testid="project-rename"]').click()
    wait(driver, lambda: [p["name"] for p in index()] == ["Pump", "Fan"])
    el(driver, "project-Fan").find_element(By.CSS_SELECTOR, '[data-testid="project-open"]').click()
    wait(driver, lambda: el(driver, "project-open-name").text == "Fan")
    assert el(driver, "cell-0-0-0").get_attribute("data-device") == "X02"
    # Delete Pump (not open), then undo.
    el(driver, "project-Pump").find_element(By.CSS_SELECTOR, '[data-testid="project-delete"]').click()
    wait(driver, lambda: [p["name"] for p in index()] == ["Fan"])
    el(driver, "project-undo-delete").click()
    wait(driver, lambda: [p["name"] for p in index()] == ["Pump", "Fan"])
    assert saved(pump["id"])["rungs"][0]["cells"][0][0]["device"] == "X02"
    # The open one cannot be deleted.
    el(driver, "project-Fan").find_element(By.CSS_SELECTOR, '[data-testid="project-delete"]').click()
    wait(driver, lambda: "open" in el(driver, "edit-message").text)
    assert len(index()) == 2
    # Reload: Fan is still open.
    driver.refresh()
    el(driver, "projects-open").click()
    wait(driver, lambda: el(driver, "project-open-name").text == "Fan")


def test_text_from_a_link_is_shown_as_text(driver, base_url, tmp_path):
    from selenium.common.exceptions import NoAlertPresentException

    hostile = "<img src=x onerror=alert(1)>"
    project = tmp_path / "hostile.json"
    project.write_text(json.dumps({
        "format": "hashigo-project", "version": 1, "machine": "minasec-u",
        "ladder": {"rungs": [{"comment": hostile, "cells": [[
            {"type": "contact", "kind": "no", "device": "X00"},
            {"type": "coil", "kind": "normal", "device": "Y00"}]]}],
                   "device_comments": {"X00": hostile}},
    }))
    fragment = subprocess.run([str(HASHIGO), "share", "--program", str(project)], check=True,
                              capture_output=True, text=True).stdout.strip()
    open_fresh(driver, base_url)
    driver.get(f"{base_url}/#{fragment}")
    wait(driver, lambda: hostile in el(driver, "rung-0").text)
    assert hostile in el(driver, "cell-0-0-0").text
    assert not driver.find_elements(By.CSS_SELECTOR, ".ladder img")
    try:
        driver.switch_to.alert
        raise AssertionError("a dialog opened")
    except NoAlertPresentException:
        pass


def test_an_exercise_link_checks_the_students_ladder(driver, base_url, tmp_path):
    exercise = tmp_path / "exercise.json"
    exercise.write_text(json.dumps({
        "format": "hashigo-project", "version": 1, "machine": "io86a",
        "ladder": {"rungs": []},
        "tests": [
            {"name": "start holds", "events": "0.1s,X00,1\n0.2s,X00,0\n",
             "expect": ["Y00 = 0 at 0.05s", "Y00 stays 1 from 0.2s to 0.5s"]},
            {"name": "stop drops", "events": "0.1s,X00,1\n0.2s,X00,0\n0.6s,X01,1\n0.7s,X01,0\n",
             "expect": ["Y00 stays 0 from 0.7s to 1s"]},
        ],
        "exercise": True,
    }))
    assert subprocess.run([str(HASHIGO), "test", "--program", str(exercise)]).returncode == 1
    fragment = subprocess.run([str(HASHIGO), "share", "--program", str(exercise)], check=True,
                              capture_output=True, text=True).stdout.strip()
    assert fragment.startswith("2.")
    open_fresh(driver, base_url)
    driver.get(f"{base_url}/#{fragment}")
    wait(driver, lambda: el(driver, "tests"), message="the tests are shown")
    # The student's view (issue #49): Check my answer, not the author's tools.
    assert el(driver, "tests").get_attribute("data-student") == "true"
    el(driver, "exercise-check").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "fail")
    assert el(driver, "test-case-1").get_attribute("data-result") in ("pass", "fail")
    assert "Y00" in el(driver, "test-case-0").text
    # The student draws the self-hold.
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F6, "X01")
    place(driver, Keys.F7, "Y00")
    keys(driver, Keys.ARROW_UP)
    place(driver, Keys.F5, "Y00", shift=True)
    el(driver, "exercise-check").click()
    wait(driver, lambda: [el(driver, f"test-case-{i}").get_attribute("data-result") for i in (0, 1)] == ["pass", "pass"])
    assert el(driver, "exercise-result").get_attribute("data-passed") == "2"
    # hashigo test agrees on the saved project.
    driver.execute_script(CAPTURE)
    el(driver, "save-json").click()
    saved = tmp_path / "answer.json"
    saved.write_text(downloads(driver, 1)["io86a-ladder.json"])
    out = subprocess.run([str(HASHIGO), "test", "--program", str(saved)], capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    assert out.stdout.endswith("2 passed, 0 failed\n")


def test_cases_are_added_edited_and_saved_with_the_project(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    el(driver, "tests-open").click()
    # The pane and its first case mount on the next frame (a race under load).
    wait(driver, lambda: el(driver, "add-test")).click()
    case = wait(driver, lambda: el(driver, "test-case-0"))
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-events"]').send_keys("0.1s,X00,1\n")
    case.find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]').send_keys("Y00 = 1 at 0.2s\nY00 = 0 at 0.05s")
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "pass")
    # A wrong expectation fails, with what was seen.
    expect = el(driver, "test-case-0").find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]')
    expect.send_keys("\nY00 = 0 at 0.3s")
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "fail")
    assert "Y00 was 1 at 300ms" in el(driver, "test-case-0").text
    raw = driver.execute_script("return localStorage.getItem('hashigo.ladder.minasec-u.v1')")
    assert json.loads(raw)["tests"][0]["expect"][-1] == "Y00 = 0 at 0.3s"


def test_the_page_does_not_move_after_an_edit_has_shown(driver, base_url):
    """Whatever follows an edit (listing, problems, the chart's rows) is
    drawn with it: nothing below the ladder moves a few frames later, when
    the user may already be clicking there (a late chart redraw once moved
    the tests pane under a click)."""
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    el(driver, "tests-open").click()
    button = wait(driver, lambda: el(driver, "add-test"))
    top = "return arguments[0].getBoundingClientRect().top + window.scrollY"
    before = driver.execute_script(top, button)
    time.sleep(0.6)  # more than two of the chart's 250 ms redraws
    assert driver.execute_script(top, button) == before


def test_a_timeline_is_recorded_from_what_the_user_clicks(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    el(driver, "ladder-write").click()
    el(driver, "mode-run").click()
    el(driver, "tests-open").click()
    el(driver, "record-test").click()
    assert el(driver, "record-test").get_attribute("aria-pressed") == "true"
    el(driver, "input-X00").click()
    wait(driver, lambda: on(driver, "lamp-Y00"))
    el(driver, "record-test").click()
    case = wait(driver, lambda: el(driver, "test-case-0"))
    events = case.find_element(By.CSS_SELECTOR, '[data-testid="test-events"]').get_attribute("value")
    assert re.fullmatch(r"\d+ms,X00,1\n", events), events
    expect = case.find_element(By.CSS_SELECTOR, '[data-testid="test-expect"]').get_attribute("value")
    assert re.fullmatch(r"Y00 = 1 at \d+ms", expect), expect
    el(driver, "run-tests").click()
    wait(driver, lambda: el(driver, "test-case-0").get_attribute("data-result") == "pass")


def scans(driver):
    return int(re.search(r"(\d+) scans", el(driver, "sim-time").text).group(1))


def seed_running(driver, base_url, speed):
    """The seed example drawn, written to the board and running at `speed`."""
    open_fresh(driver, base_url)
    Select(el(driver, "example")).select_by_value("seed-test")
    wait(driver, lambda: el(driver, "cell-4-0-9").get_attribute("data-device") == "C0R")
    Select(el(driver, "speed")).select_by_value(speed)
    el(driver, "run").click()
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-on") == "0", message="live states")


def test_run_the_drawn_ladder_and_watch_its_devices(driver, base_url):
    seed_running(driver, base_url, "max")
    assert el(driver, "cell-0-0-1").get_attribute("data-on") == "0"  # X01: off
    assert el(driver, "cell-0-0-9").get_attribute("data-on") == "0"  # Y00: off
    assert el(driver, "cell-0-0-4").get_attribute("data-on") is None, "a wire shows no device"
    # Power as the machine computed it: nothing gets past X00 yet, the
    # NC contact of X01 conducts but has no power to pass.
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-powered") == "0")
    assert el(driver, "cell-0-0-1").get_attribute("data-powered") == "0"
    assert el(driver, "cell-0-0-9").get_attribute("data-powered") == "0"
    assert el(driver, "cell-0-0-5").get_attribute("data-powered") == "0", "a wire too"
    el(driver, "watch-input").send_keys("C0", Keys.ENTER)
    assert el(driver, "watch-C0")
    el(driver, "input-X00").click()
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-on") == "1")
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="Y00 on")
    assert el(driver, "cell-0-1-0").get_attribute("data-on") == "1", "the Y00 contact shows Y00 on"
    for cell in ["cell-0-0-0", "cell-0-0-1", "cell-0-0-5", "cell-0-0-9", "cell-0-1-0"]:
        wait(driver, lambda: el(driver, cell).get_attribute("data-powered") == "1", message=f"{cell} powered")
    el(driver, "input-X00").click()
    # The start button released: its contact off and unpowered, the
    # self-hold carrying the power.
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-powered") == "0")
    assert el(driver, "cell-0-1-0").get_attribute("data-powered") == "1"
    assert el(driver, "cell-0-0-9").get_attribute("data-powered") == "1"
    # The counter's coil shows its count; the board's display climbs too.
    count = lambda: el(driver, "cell-2-1-9").find_element(By.CSS_SELECTOR, ".val").get_attribute("data-value")
    wait(driver, lambda: count() not in (None, "", "0"), timeout=30, message="the count on C0's coil")
    wait(driver, lambda: el(driver, "seg7").text not in ("", "00"), message="the 7-segment count")
    wait(driver, lambda: "(" in el(driver, "watch-C0").text and not el(driver, "watch-C0").text.endswith("(0)"),
         timeout=30, message="the count shows in the watch table")
    # Step one scan at a time, paused.
    el(driver, "step-scan").click()
    before = scans(driver)
    el(driver, "step-scan").click()
    wait(driver, lambda: scans(driver) == before + 1)
    time.sleep(0.3)
    assert scans(driver) == before + 1, "paused after a step"
    el(driver, "step-instr").click()
    wait(driver, lambda: el(driver, "step-at").text.startswith("step "))
    assert "step-clock" in [b.get_attribute("data-testid") for b in driver.find_elements(By.CSS_SELECTOR, ".run-controls button")]


def test_a_one_scan_pulse_is_marked_in_the_frame_after_it(driver, base_url):
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("io86a")
    wait(driver, lambda: el(driver, "palette"))
    el(driver, "new-ladder").click()
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F8, "PLS M00")
    place(driver, Keys.F5, "M00")
    place(driver, Keys.F8, "SET Y02")
    assert "PLS M00" in el(driver, "il-listing").text
    el(driver, "run").click()
    wait(driver, lambda: el(driver, "cell-1-0-0").get_attribute("data-powered") == "0")
    driver.execute_script("""
        window.marks = [];
        const cell = document.querySelector('[data-testid="cell-1-0-0"]');
        new MutationObserver(() => window.marks.push(cell.getAttribute('data-pulsed')))
          .observe(cell, {attributes: true, attributeFilter: ['data-pulsed']});""")
    el(driver, "io86a-input-X00").click()
    wait(driver, lambda: "1" in driver.execute_script("return window.marks"),
         message="M00's one-scan pulse is marked")
    wait(driver, lambda: el(driver, "cell-1-0-9").get_attribute("data-on") == "1", message="Y02 set by it")
    # M00 itself is off again in every frame's scan.
    assert el(driver, "cell-1-0-0").get_attribute("data-on") == "0"


def test_inputs_driven_from_the_ladder_and_the_stepped_element(driver, base_url):
    seed_running(driver, base_url, "max")
    # A click on the X00 contact drives X00 (held until released).
    el(driver, "cell-0-0-0").click()
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "1", message="Y00 latched")
    assert el(driver, "cell-0-0-0").get_attribute("data-forced") == "1"
    assert "X00 = 1" in el(driver, "forces").text
    el(driver, "force-X00").find_element(By.CSS_SELECTOR, '[data-testid="force-release"]').click()
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-on") == "0", message="released")
    assert "X00" not in el(driver, "forces").text
    # An output is not an input: refused with the engine's words.
    el(driver, "cell-3-0-0").click()  # C0's contact
    wait(driver, lambda: "only an input" in el(driver, "edit-message").text)
    # Shift+click: X01 (stop) on for one scan drops the self-hold.
    ActionChains(driver).key_down(Keys.SHIFT).click(el(driver, "cell-0-0-1")).key_up(Keys.SHIFT).perform()
    wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-on") == "0", message="stopped by a pulse")
    assert el(driver, "cell-0-0-1").get_attribute("data-on") == "0", "the pulse is over"
    # Step one instruction (the first of a scan): its element is outlined,
    # its step lit.
    el(driver, "step-scan").click()
    el(driver, "step-instr").click()
    wait(driver, lambda: el(driver, "step-at").text.startswith("step 0"))
    wait(driver, lambda: "stepped" in el(driver, "cell-0-0-0").get_attribute("class"))
    # The listing (its pane drawn when first shown) lights that step.
    el(driver, "il-listing")
    wait(driver, lambda: [c.get_attribute("data-step")
                          for c in driver.find_elements(By.CSS_SELECTOR, ".listing .line.current")] == ["0"],
         message="the stepped instruction lit in the listing")


def live_scan(driver):
    """The last recorded scan, which the travel bar marks while live."""
    return int(el(driver, "travel-at").get_attribute("data-mark"))


# The live frame's measure (issue #26; with a plant, issue #52): the
# requestAnimationFrame deltas over 3 s.
FRAMES = """
    const done = arguments[arguments.length - 1];
    const deltas = []; let last = null; const end = performance.now() + 3000;
    function frame(t) { if (last !== null) deltas.push(t - last); last = t;
      if (t < end) requestAnimationFrame(frame); else done(deltas); }
    requestAnimationFrame(frame);"""


def toggling_rungs(count=200):
    """`count` rungs of 10 columns whose every coil toggles every scan
    (`NC Rn.m -> (Rn.m)`, the AVR PLC's bits)."""
    rungs = []
    for i in range(count):
        bit = f"R{i // 8}.{i % 8}"
        rungs.append({"cells": [[{"type": "contact", "kind": "nc", "device": bit}]
                                + [{"type": "wire"}] * 8
                                + [{"type": "coil", "kind": "normal", "device": bit}]]})
    return rungs


def open_toggling_ladder(driver, base_url, tmp_path, size, version=1, **more):
    """Opens `toggling_rungs()` on the AVR PLC in a window of `size` (a
    project file of `version` with `more` fields, a plant's setup) and
    waits for its last rung."""
    project = tmp_path / "r200.json"
    project.write_text(json.dumps({"format": "hashigo-project", "version": version, "machine": "avr-plc",
                                   "ladder": {"rungs": toggling_rungs()}, **more}))
    driver.set_window_size(*size)
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("avr-plc")
    wait(driver, lambda: el(driver, "palette"))
    el(driver, "open-file").send_keys(str(project))
    wait(driver, lambda: el(driver, "cell-199-0-9").get_attribute("data-device") == "R24.7")


def frame_stats(deltas):
    """p50, p95 and the longest of a run's frame deltas."""
    d = sorted(deltas)
    pick = lambda q: round(d[min(len(d) - 1, int(q * len(d)))], 2)
    return {"p50": pick(0.5), "p95": pick(0.95), "max": round(d[-1], 2), "frames": len(d)}


def test_a_200_rung_ladder_colours_live_at_the_display_rate(driver, base_url, tmp_path):
    """Measures frame times and holds issue #53's bound (running within
    1.15x of paused, each the median of three runs' p95): 200 rungs of 10
    columns on the AVR PLC, every coil toggling every scan, run flat out in
    a 1600x1100 window; the p95 of requestAnimationFrame deltas, running
    and paused, three runs of 3 s each, go to figures.json with their
    medians, and the scans simulated per second while running
    (docs/performance.md)."""
    open_toggling_ladder(driver, base_url, tmp_path, (1600, 1100))
    Select(el(driver, "speed")).select_by_value("max")
    driver.set_script_timeout(30)

    runs = {"running": [], "paused": []}
    # The AVR PLC runs its own program from power-up: the one run control
    # says Stop (issue #45); stopped, Run writes the drawing, and later
    # rounds resume from Pause.
    if el(driver, "run").get_attribute("aria-pressed") == "true":
        el(driver, "run").click()
        wait(driver, lambda: el(driver, "run").get_attribute("aria-pressed") == "false")
    for round_ in range(3):
        el(driver, "run" if round_ == 0 else "pause").click()
        wait(driver, lambda: el(driver, "cell-0-0-9").get_attribute("data-powered") in ("0", "1"))
        first_scan = live_scan(driver)
        running = driver.execute_async_script(FRAMES)
        scans = live_scan(driver) - first_scan
        # Toggling every scan, each coil changed between any two frames.
        assert el(driver, "cell-100-0-9").get_attribute("data-pulsed") == "1"
        assert el(driver, "cell-199-0-0").get_attribute("data-pulsed") == "1"
        el(driver, "pause").click()
        paused = driver.execute_async_script(FRAMES)
        assert len(running) > 30 and len(paused) > 30
        runs["running"].append(frame_stats(running) | {"scans_per_s": round(scans / 3)})
        runs["paused"].append(frame_stats(paused))

    frames = {}
    for state in ("running", "paused"):
        p95s = sorted(r["p95"] for r in runs[state])
        frames[f"ladder_200_rungs_{state}_frame_ms"] = {"median_p95": p95s[1], "runs": runs[state]}
    record_figures(frames)
    print(frames)
    # Issue #53's "within 1.15x of paused", the median of the three runs.
    running, paused = (frames[f"ladder_200_rungs_{s}_frame_ms"]["median_p95"] for s in ("running", "paused"))
    assert running <= 1.15 * paused, frames


# Counts, over 2 s, the changes of `data-powered` on two cells.
CHANGES = """
    const [a, b, done] = arguments; const seen = {a: 0, b: 0};
    const watch = (cell, key) => new MutationObserver(m => { seen[key] += m.length; })
        .observe(cell, {attributes: true, attributeFilter: ["data-powered"]});
    watch(a, "a"); watch(b, "b");
    setTimeout(() => done(seen), 2000);"""


def test_rungs_off_screen_are_brought_up_to_date_in_turn_and_on_screen_every_frame(driver, base_url, tmp_path):
    """A running frame brings the rungs on screen up to date every frame
    and those off screen once in sixteen frames (docs/performance.md,
    "The plant's frame, taken apart"): counted with a MutationObserver on a coil on screen and
    one far below, every coil toggling every scan at x1; scrolled to, the
    far rung is brought up to date every frame."""
    open_toggling_ladder(driver, base_url, tmp_path, (1366, 768))
    if el(driver, "run").get_attribute("aria-pressed") == "true":
        el(driver, "run").click()
        wait(driver, lambda: el(driver, "run").get_attribute("aria-pressed") == "false")
    el(driver, "run").click()
    near, far = el(driver, "cell-0-0-9", reveal=False), el(driver, "cell-150-0-9", reveal=False)
    wait(driver, lambda: far.get_attribute("data-powered") in ("0", "1"), message="the far rung shown in turn")
    driver.set_script_timeout(10)
    time.sleep(0.2)
    seen = driver.execute_async_script(CHANGES, near, far)
    # About 120 frames: the near coil's power shows anew in each that ran
    # an odd count of scans (it toggles every scan), the far one's only in
    # one frame of sixteen.
    assert seen["a"] >= 20, seen
    assert 1 <= seen["b"] <= seen["a"] / 4, seen
    # Scrolled to the far rung: the near one is off screen now.
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", far)
    time.sleep(0.2)
    seen = driver.execute_async_script(CHANGES, near, far)
    assert seen["b"] >= 20 and 1 <= seen["a"] <= seen["b"] / 4, seen
    assert severe_console_messages(driver) == []


def test_an_io86a_timer_coil_shows_current_and_preset(driver, base_url):
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("io86a")
    wait(driver, lambda: el(driver, "palette"))
    Select(el(driver, "example")).select_by_value("timer")
    wait(driver, lambda: "K19" in el(driver, "il-listing").text)
    timer = driver.find_element(By.CSS_SELECTOR, '.ladder [data-device="T00"][data-kind="coil"]')
    assert "K19" in timer.text
    el(driver, "watch-input").send_keys("T00", Keys.ENTER)
    el(driver, "run").click()
    wait(driver, lambda: (timer.find_element(By.CSS_SELECTOR, ".val").get_attribute("data-value") or "0") != "0",
         message="T00 counts on its coil")
    wait(driver, lambda: "/K19)" in el(driver, "watch-T00").text, message="current / preset in the watch table")


def test_taps_alone_place_a_contact_and_a_coil(driver, base_url):
    """No Return key on a touch screen: a cell, a palette item, a chip, OK."""
    open_fresh(driver, base_url)
    el(driver, "new-ladder").click()

    def tap_entry(palette, device):
        el(driver, palette).click()
        chips = wait(driver, lambda: [b for b in driver.find_elements(
            By.CSS_SELECTOR, '[data-testid="device-options"] button') if b.text.split()[0] == device])
        chips[0].click()
        assert el(driver, "device-input").get_attribute("value") == device
        el(driver, "device-ok").click()
        wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="device-input"]'))

    el(driver, "cell-0-0-0").click()
    tap_entry("palette-no", "X00")
    wait(driver, lambda: el(driver, "cell-0-0-0").get_attribute("data-device") == "X00")
    tap_entry("palette-coil", "Y00")
    wait(driver, lambda: "ST   Y00" in el(driver, "il-listing").text or "Y00" in el(driver, "il-listing").text)
    assert any(c.get_attribute("data-device") == "Y00" and c.get_attribute("data-kind") == "coil"
               for c in driver.find_elements(By.CSS_SELECTOR, '[data-testid="ladder"] [data-device]'))


def test_the_key_map_takes_the_focus_and_closes_on_escape(driver, base_url):
    open_fresh(driver, base_url)
    focus_ladder(driver)
    el(driver, "keys").click()
    wait(driver, lambda: driver.switch_to.active_element.get_attribute("data-testid") == "keymap",
         message="the key map has the focus")
    keys(driver, Keys.ESCAPE)
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="keymap"]'))
    assert driver.switch_to.active_element.get_attribute("data-testid") == "ladder"


def test_a_projects_plant_is_kept_when_the_page_saves_it(driver, base_url, tmp_path):
    # Issue #50: a project may hold a plant (made on the command line);
    # the page does not show plants yet (issue #52) but must not drop one
    # when it keeps the project.
    project = json.loads((ROOT / "engine/programs/minasec-u/conveyor.json").read_text())
    del project["exercise"]
    project["plant"] = {"name": "conveyor", "params": {"interval": "5000"},
                        "faults": ["outfeed stuck 0 from 30s"]}
    path = tmp_path / "plant.json"
    path.write_text(json.dumps(project))
    fragment = subprocess.run([str(HASHIGO), "share", "--program", str(path)], check=True,
                              capture_output=True, text=True).stdout.strip()
    assert fragment.startswith("5."), fragment
    wanted = json.loads(subprocess.run([str(HASHIGO), "unshare", fragment], check=True,
                                       capture_output=True, text=True).stdout)["plant"]
    open_fresh(driver, base_url)
    driver.get(f"{base_url}/#{fragment}")
    wait(driver, lambda: el(driver, "shared-banner"), message="the banner")
    el(driver, "shared-keep").click()
    wait(driver, lambda: driver.execute_script("return localStorage.getItem('hashigo.projects.v1')"))
    index = json.loads(driver.execute_script("return localStorage.getItem('hashigo.projects.v1')"))
    [entry] = index["projects"]
    kept = json.loads(driver.execute_script("return localStorage.getItem(arguments[0])",
                                            f"hashigo.project.{entry['id']}.v1"))
    assert kept.get("plant") == wanted, kept.get("plant")
