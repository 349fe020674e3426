"""End-to-end: the PLC-IO86A workspace in headless Chromium."""

import time

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import el, on, open_fresh, severe_console_messages, wait


def open_io86a(driver, base_url):
    open_fresh(driver, base_url)
    Select(el(driver, "machine")).select_by_value("io86a")
    wait(driver, lambda: el(driver, "io86a-terminal"))


def type_at_terminal(driver, line):
    before = el(driver, "io86a-terminal").text
    el(driver, "io86a-terminal-input").send_keys(line + Keys.ENTER)
    wait(driver, lambda: el(driver, "io86a-terminal").text != before)
    return el(driver, "io86a-terminal").text


def test_the_manuals_blink_runs_and_the_choice_is_remembered(driver, base_url):
    open_io86a(driver, base_url)
    assert "LDI T01" in el(driver, "io86a-program-text").get_attribute("value")
    # Stopped until Run (docs/app.md, "Stopped until Run").
    assert el(driver, "sim-time").get_attribute("data-state") == "stopped"
    el(driver, "run").click()
    seen = set()

    def toggled():
        seen.add(on(driver, "io86a-lamp-Y00"))
        return seen == {True, False}

    wait(driver, toggled, timeout=5, message="Y00 blinks")
    driver.refresh()
    wait(driver, lambda: el(driver, "io86a-terminal"))
    assert Select(el(driver, "machine")).first_selected_option.get_attribute("value") == "io86a"
    assert severe_console_messages(driver) == []


def test_the_terminal_edits_runs_and_reads(driver, base_url):
    open_io86a(driver, base_url)
    type_at_terminal(driver, "^C")
    assert el(driver, "io86a-state").text in ("stopped", "停止中")
    # Outputs keep their state across a program change, as on the device:
    # the blink may have stopped with Y00 on, so reset every Y first.
    type_at_terminal(driver, "@")
    type_at_terminal(driver, "NA")
    for line in ["LD X00", "OUT Y02", "END", "Q"]:
        type_at_terminal(driver, line)
    screen = type_at_terminal(driver, "L")
    assert screen.endswith("1 LD X00\n2 OUT Y02\n3 END\n>"), screen
    type_at_terminal(driver, "R")
    el(driver, "io86a-input-X00").click()
    wait(driver, lambda: on(driver, "io86a-lamp-Y02"), message="the entered program runs")
    screen = type_at_terminal(driver, "Y?")
    assert "Y:00000100" in screen, screen
    el(driver, "io86a-terminal-ctrl-c").click()
    wait(driver, lambda: el(driver, "io86a-terminal").text.endswith(">"))


def test_servo_follows_the_analog_slider(driver, base_url):
    open_io86a(driver, base_url)
    for command in ["X04A:401:100", "Y03R"]:
        type_at_terminal(driver, command)
    text = el(driver, "io86a-program-text")
    text.clear()
    text.send_keys("1 LD M57\n2 MOV\n3 D06\n4 D04\n5 OUT Y03\n6 END\n")
    el(driver, "io86a-program-load").click()
    slider = el(driver, "io86a-analog-X04")
    driver.execute_script(
        "arguments[0].value = 5000; arguments[0].dispatchEvent(new Event('input', {bubbles: true}));", slider
    )
    wait(driver, lambda: "2500 µs" in el(driver, "io86a-out-Y03").text, message="5 V → 2500 µs")
    driver.execute_script(
        "arguments[0].value = 2500; arguments[0].dispatchEvent(new Event('input', {bubbles: true}));", slider
    )
    wait(driver, lambda: "1500 µs" in el(driver, "io86a-out-Y03").text, message="2.5 V → 1500 µs")


def test_program_errors_block_loading(driver, base_url):
    open_io86a(driver, base_url)
    text = el(driver, "io86a-program-text")
    text.clear()
    text.send_keys("LD X00\nOUT T00\n")
    wait(driver, lambda: "line 2" in el(driver, "io86a-program-error").text)
    assert "K10" in el(driver, "io86a-program-error").text
    assert not el(driver, "io86a-program-load").is_enabled()


def test_two_linked_devices(driver, base_url):
    open_io86a(driver, base_url)
    el(driver, "io86a-two").click()
    a = el(driver, "io86a-program-text")
    a.clear()
    a.send_keys("LD X00\nSETS Y00\nLDI X00\nRSTS Y00\nEND\n")
    el(driver, "io86a-program-load").click()
    b = el(driver, "io86a-b-program-text")
    b.send_keys("END\n")
    el(driver, "io86a-b-program-load").click()
    el(driver, "io86a-input-X00").click()
    wait(driver, lambda: on(driver, "io86a-b-lamp-Y00"), message="A's X00 lights B's Y00")
    el(driver, "io86a-input-X00").click()
    wait(driver, lambda: not on(driver, "io86a-b-lamp-Y00"), message="and puts it out")
    time.sleep(0.2)
    driver.save_screenshot(str(__import__("pathlib").Path(__file__).parent / "artifacts" / "io86a.png"))


def test_ir_remote_buttons_drive_y00_while_held(driver, base_url):
    from selenium.webdriver.common.action_chains import ActionChains

    open_io86a(driver, base_url)
    type_at_terminal(driver, "X07I:10EF")
    text = el(driver, "io86a-program-text")
    text.clear()
    text.send_keys("LD M57\nCMP K30727 D03\nLD M61\nOUT Y00\nEND\n")
    el(driver, "io86a-program-load").click()
    button = el(driver, "io86a-ir-A")
    ActionChains(driver).click_and_hold(button).perform()
    wait(driver, lambda: on(driver, "io86a-lamp-Y00"), message="A held: D03 = 30727")
    ActionChains(driver).release(button).perform()
    wait(driver, lambda: not on(driver, "io86a-lamp-Y00"), message="released")
    assert "10EF7807" in type_at_terminal(driver, ".")
