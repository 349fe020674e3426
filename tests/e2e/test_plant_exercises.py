"""End-to-end: an exercise per plant (issue #52). Each plant's exercise
opens from the start screen's exercises with its plant coupled on its
machine (MINASEC-U: their bit inputs and outputs suffice), and from the
gallery's plants; the room light drawn by keys passes Check my answer; the
plant dock with a plant chosen passes axe; on a phone the plant is drawn
above the ladder, on a tablet and a laptop only in the tools dock
(screenshots of each)."""

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from test_app import drawn, el, severe_console_messages, wait
from test_ladder import focus_ladder, place

# Each plant, its exercise's machine and a signal its drawing shows.
PLANTS = [
    ("conveyor", "minasec-u", "infeed"),
    ("tank", "minasec-u", "low"),
    ("traffic", "minasec-u", "button"),
    ("door", "minasec-u", "top"),
    ("sorter", "minasec-u", "part"),
    ("room-light", "minasec-u", "dark"),
]


def shown(driver, testid):
    return any(e.is_displayed() for e in driver.find_elements(By.CSS_SELECTOR, f'[data-testid="{testid}"]'))


def exercise_link(driver, plant):
    """The start screen's exercise of `plant`, its list shown."""
    el(driver, "start-exercise").click()
    selector = f'[data-start-part="exercise"] [data-plant="{plant}"]'
    wait(driver, lambda: any(e.is_displayed() for e in driver.find_elements(By.CSS_SELECTOR, selector)),
         message=f"the {plant} exercise is offered")
    return driver.find_element(By.CSS_SELECTOR, selector)


def coupled(driver, plant, machine, signal):
    """The exercise of `plant` is open on `machine` with its plant coupled."""
    wait(driver, lambda: not shown(driver, "start"), message="the start screen closes")
    wait(driver, lambda: el(driver, "machine", reveal=False).get_attribute("value") == machine,
         timeout=30, message=f"{plant} opens on {machine}")
    wait(driver, lambda: f"{plant}" in el(driver, "exercise-task", reveal=False).text,
         message=f"the {plant} task is shown")
    wait(driver, lambda: el(driver, "plant-select").get_attribute("value") == plant,
         message=f"{plant} is chosen")
    wait(driver, lambda: driver.find_elements(By.CSS_SELECTOR, f'[data-testid="plant-sig-{signal}"]'),
         timeout=30, message=f"{plant} is drawn")
    # Coupled with the machine's default wiring, nothing refused.
    assert el(driver, f"wiring-device-{signal}").get_attribute("value") != ""
    assert not driver.find_elements(By.CSS_SELECTOR, ".plant-wiring tr.refused")


@pytest.mark.first_visit
def test_each_plants_exercise_opens_from_the_start_screen_with_its_plant_coupled(driver, base_url):
    driver.get(base_url)
    wait(driver, lambda: shown(driver, "start-exercise"))
    for i, (plant, machine, signal) in enumerate(PLANTS):
        if i:
            el(driver, "help-start").click()
            wait(driver, lambda: shown(driver, "start-exercise"))
        exercise_link(driver, plant).click()
        coupled(driver, plant, machine, signal)
    # The gallery offers them too, as a group of plants on every machine.
    el(driver, "help-start").click()
    wait(driver, lambda: shown(driver, "start-example"))
    el(driver, "start-example").click()
    wait(driver, lambda: shown(driver, "start-plant-door"), message="the gallery's plants")
    cards = [e for e in driver.find_elements(By.CSS_SELECTOR, ".start-plants [data-plant]") if e.is_displayed()]
    assert [c.get_attribute("data-plant") for c in cards] == [p for p, _, _ in PLANTS]
    assert "Garage door" in el(driver, "start-plant-door").text
    el(driver, "start-plant-door").click()
    coupled(driver, "door", "minasec-u", "top")
    assert severe_console_messages(driver) == []


@pytest.mark.first_visit
def test_the_troubleshooting_exercise_opens_from_the_gallery_and_passes_once_named(driver, base_url):
    """The troubleshooting exercise is in the gallery's plants as in the
    exercises: its right ladder, its plant and its hidden fault; named,
    Check my answer passes."""
    from test_classroom import result

    driver.get(base_url)
    wait(driver, lambda: shown(driver, "start-example"))
    el(driver, "start-example").click()
    wait(driver, lambda: shown(driver, "start-plant-conveyor-fault"), message="the gallery's plants")
    assert "Troubleshooting" in el(driver, "start-plant-conveyor-fault").text
    el(driver, "start-plant-conveyor-fault").click()
    wait(driver, lambda: "Troubleshooting" in el(driver, "exercise-task", reveal=False).text,
         timeout=30, message="its task is shown")
    coupled(driver, "conveyor", "minasec-u", "infeed")
    # The ladder as handed out (the right one), the fault hidden.
    assert el(driver, "cell-0-0-0", reveal=False)
    assert "Which fault?" in el(driver, "fault-report").text
    assert not driver.find_elements(By.CSS_SELECTOR, '[data-testid="plant-fault-add"]')
    Select(el(driver, "fault-report-signal")).select_by_value("infeed")
    Select(el(driver, "fault-report-kind")).select_by_value("stuck 0")
    el(driver, "exercise-check").click()
    wait(driver, lambda: drawn(driver, "exercise-result"))
    wait(driver, lambda: result(driver) == ("3", "3"), timeout=40,
         message="Check my answer passes once the fault is named")
    assert severe_console_messages(driver) == []


@pytest.mark.first_visit
def test_the_room_light_exercise_drawn_by_keys_passes_check_my_answer(driver, base_url):
    from test_classroom import result

    driver.get(base_url)
    wait(driver, lambda: shown(driver, "start-exercise"))
    exercise_link(driver, "room-light").click()
    coupled(driver, "room-light", "minasec-u", "dark")
    # The empty ladder the student starts from does not pass.
    el(driver, "exercise-check").click()
    wait(driver, lambda: drawn(driver, "exercise-result"))
    wait(driver, lambda: result(driver)[1] not in (None, "0"), timeout=40)
    assert result(driver)[0] != result(driver)[1], result(driver)
    # The reference answer: the lamp on while the sensor says dark.
    focus_ladder(driver)
    place(driver, Keys.F5, "X00")
    place(driver, Keys.F7, "Y00")
    assert el(driver, "problems").text.strip() == "No problems."
    el(driver, "exercise-check").click()
    wait(driver, lambda: result(driver)[0] == result(driver)[1], timeout=40,
         message="Check my answer passes")
    assert severe_console_messages(driver) == []


@pytest.mark.parametrize("plant,machine,signal", [PLANTS[0], PLANTS[1], PLANTS[3]])
def test_the_plant_dock_with_a_plant_chosen_passes_axe(driver, base_url, plant, machine, signal):
    from test_access import AXE, violations

    assert AXE.exists(), "run scripts/setup.sh (it installs axe-core)"
    driver.set_window_size(1366, 768)
    driver.get(base_url)
    el(driver, "help-start").click()
    wait(driver, lambda: shown(driver, "start-exercise"))
    exercise_link(driver, plant).click()
    coupled(driver, plant, machine, signal)
    Select(el(driver, "speed")).select_by_value("10")
    el(driver, "run").click()
    el(driver, "plant-select")  # the Plant tab shown
    assert violations(driver) == []


@pytest.mark.parametrize("name", ["laptop", "tablet", "phone"])
def test_the_plant_above_the_ladder_on_a_phone_only(tmp_path, base_url, artifacts, name):
    from test_screens import no_sideways_overflow, screen_driver

    driver = screen_driver(tmp_path, name)
    try:
        driver.get(base_url)
        el(driver, "help-start").click()
        wait(driver, lambda: shown(driver, "start-exercise"))
        exercise_link(driver, "conveyor").click()
        coupled(driver, "conveyor", "minasec-u", "infeed")
        # Back to the ladder: the tools' sheet down on a phone.
        if name == "phone" and el(driver, "dock-bottom", reveal=False).get_attribute("data-sheet") == "true":
            el(driver, "dock-bottom-toggle", reveal=False).click()
        driver.execute_script("window.scrollTo(0, 0)")
        above = driver.find_elements(By.CSS_SELECTOR, '[data-testid="plant-above"]')
        if name != "phone":
            assert above == [], "laptops and tablets keep the plant in the tools dock"
        else:
            wait(driver, lambda: shown(driver, "plant-above"), message="the plant above the ladder")
            box = driver.execute_script(
                "const a = document.querySelector('[data-testid=plant-above]').getBoundingClientRect();"
                "const l = document.querySelector('[data-testid=ladder]').getBoundingClientRect();"
                "return [a.top, a.bottom, l.top, l.height, window.innerHeight];")
            top, bottom, ladder_top, ladder_height, height = box
            assert bottom <= ladder_top + 1, box
            # Compact: the ladder keeps room for rungs.
            assert bottom - top <= 0.25 * height, box
            assert ladder_height >= 160, box
        assert no_sideways_overflow(driver)
        driver.save_screenshot(str(artifacts / f"plant-exercise-conveyor-{name}.png"))
    finally:
        driver.quit()
