"""End-to-end: the Arduino PLC and AVR simplified PLC workspaces."""

from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import el, on, open_fresh, severe_console_messages, wait


def choose(driver, base_url, machine, ready):
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value(machine)
    wait(driver, lambda: el(driver, ready))


def replace_program(driver, prefix, text):
    area = el(driver, f"{prefix}-program-text")
    area.send_keys(Keys.CONTROL, "a")
    area.send_keys(Keys.DELETE)
    area.send_keys(text)
    el(driver, f"{prefix}-program-load").click()


def test_arduino_self_hold_monitor_and_quirk(driver, base_url):
    choose(driver, base_url, "arduino-plc", "arduino-monitor")
    # Stopped until started: the sketch's own program, loaded and run from
    # its pane (Run would write the drawing).
    el(driver, "arduino-program-load").click()
    el(driver, "arduino-input-X000").click()
    wait(driver, lambda: on(driver, "arduino-lamp-Y000"), message="start")
    el(driver, "arduino-input-X000").click()
    assert on(driver, "arduino-lamp-Y000"), "holds itself"
    el(driver, "arduino-input-X001").click()
    wait(driver, lambda: not on(driver, "arduino-lamp-Y000"), message="stop")

    box = el(driver, "arduino-monitor-input")
    box.send_keys("l" + Keys.ENTER)
    wait(driver, lambda: "JUMP 000" in el(driver, "arduino-monitor").text)
    assert "LD X000\nOR Y000\nANDN X001\nOUT Y000" in el(driver, "arduino-monitor").text
    box.send_keys("d" + Keys.ENTER)
    wait(driver, lambda: "disabled" in el(driver, "arduino-state").text)

    replace_program(driver, "arduino", "LD X000\nOUT Y001\nEND\n")
    el(driver, "arduino-input-X001").click()  # X001 off again
    el(driver, "arduino-input-X000").click()  # X000 on
    wait(driver, lambda: on(driver, "arduino-lamp-Y001"), message="LD X000 / OUT Y001")
    el(driver, "arduino-quirk").click()
    wait(driver, lambda: not on(driver, "arduino-lamp-Y001"), message="the sketch's pop order")
    assert severe_console_messages(driver) == []


def test_arduino_warns_about_running_into_erased_eeprom(driver, base_url):
    choose(driver, base_url, "arduino-plc", "arduino-monitor")
    area = el(driver, "arduino-program-text")
    area.send_keys(Keys.CONTROL, "a")
    area.send_keys(Keys.DELETE)
    area.send_keys("LD X000\nOUT Y000\n")
    wait(driver, lambda: "JUMP 255" in el(driver, "arduino-warning").text)
    area.send_keys("END\n")
    wait(driver, lambda: not driver.find_elements("css selector", '[data-testid="arduino-warning"]'))


def test_avr_named_bits_and_the_tof_warning(driver, base_url):
    choose(driver, base_url, "avr-plc", "avr-program-text")
    # Powered off until started: the program's own named bits, loaded
    # from its pane (Run would write the drawing, named by addresses).
    el(driver, "avr-program-load").click()
    for name in ["INPUT1", "INPUT2"]:
        el(driver, f"avr-input-{name}").click()
    wait(driver, lambda: on(driver, "avr-lamp-COIL1") and on(driver, "avr-lamp-COIL2"))
    el(driver, "avr-input-INPUT1").click()
    wait(driver, lambda: not on(driver, "avr-lamp-COIL1"))
    assert on(driver, "avr-lamp-COIL2"), "COIL2 holds itself"
    el(driver, "avr-input-INPUT3").click()
    wait(driver, lambda: not on(driver, "avr-lamp-COIL2"))

    replace_program(
        driver,
        "avr",
        ".equ Run_R=4\n.equ Run_B=Bit0\n.equ E_Stop_R=6\n.equ E_Stop_B=Bit7\n.dseg\nPLC_Timer_Top:\n"
        "E_Stop_Timer: .byte 2\n.cseg\n.db Load_A,Run_R,Run_B,0\n"
        ".db TOF,LOW(E_Stop_Timer),LOW(1000/Scan),HIGH(1000/Scan)\n.db Coil_A,E_Stop_R,E_Stop_B,0\n"
        ".db End_PLC,0,0,0\n",
    )
    assert "TOF" in el(driver, "avr-warning").text
    wait(driver, lambda: on(driver, "avr-lamp-E_Stop"), timeout=2, message="on after power-up")
    wait(driver, lambda: not on(driver, "avr-lamp-E_Stop"), timeout=5, message="off after 1 s")


def test_avr_reloading_a_program_keeps_its_lamps_live(driver, base_url):
    """Issue #11: load a program, load it again with the same bit names,
    switch an input on: its lamp must still light (a keyed row used to
    stay bound to the replaced signals)."""
    choose(driver, base_url, "avr-plc", "avr-program-text")
    el(driver, "avr-program-load").click()
    el(driver, "avr-program-load").click()
    el(driver, "avr-input-INPUT1").click()
    el(driver, "avr-input-INPUT2").click()
    wait(driver, lambda: on(driver, "avr-lamp-COIL1"), message="COIL1 after a reload")
    # A switch keeps its level across a reload, and drives the new program.
    el(driver, "avr-program-load").click()
    assert el(driver, "avr-input-INPUT1").get_attribute("aria-pressed") == "true"
    el(driver, "avr-input-INPUT2").click()
    wait(driver, lambda: not on(driver, "avr-lamp-COIL1"), message="COIL1 off with INPUT2 off")
    assert severe_console_messages(driver) == []


def test_arduino_and_avr_saves_are_checked_and_migrated(driver, base_url):
    """Issue #11: every workspace's save goes through one checked helper.
    A corrupt save is kept aside and reported; a plain-text save from the
    previous version is taken over."""
    import re

    open_fresh(driver, base_url)
    driver.execute_script(
        "localStorage.setItem('hashigo.avr-plc.v2', '{not json');"
        "localStorage.setItem('hashigo.arduino-plc.v1', arguments[0]);",
        "; taken over\n0 LD X001\n1 OUT Y001\n2 END\n",
    )
    driver.refresh()
    # Reported when the AVR PLC's workspace is restored: when it is first
    # shown (it arrives with its part, issue #53).
    assert not driver.find_elements("css selector", "[data-testid=notice]")
    Select(el(driver, "machine")).select_by_value("avr-plc")
    notice = wait(driver, lambda: el(driver, "notice"))
    match = re.search(r"(hashigo\.avr-plc\.v2\.corrupt\.\d+)", notice.text)
    assert match, notice.text
    kept = driver.execute_script("return localStorage.getItem(arguments[0]);", match.group(1))
    assert kept == "{not json"
    Select(el(driver, "machine")).select_by_value("arduino-plc")
    area = wait(driver, lambda: el(driver, "arduino-program-text"))
    assert "taken over" in area.get_attribute("value")
    el(driver, "arduino-program-load").click()
    el(driver, "arduino-input-X001").click()
    wait(driver, lambda: on(driver, "arduino-lamp-Y001"), message="the taken-over program runs")
    # Edits are saved in the checked form.
    area.send_keys("; more\n")
    saved = driver.execute_script("return localStorage.getItem('hashigo.arduino-plc.v2');")
    assert saved is not None and '"program"' in saved, saved
