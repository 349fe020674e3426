"""End-to-end: the first visit is never blank (issue #29, first part):
index.html paints a loading screen without any script, the app replaces
it, and when the app cannot start the screen says what to do."""

from selenium.webdriver.common.by import By

from test_app import el, open_fresh, wait


def test_the_app_replaces_the_loading_screen(driver, base_url):
    open_fresh(driver, base_url)
    wait(driver, lambda: not driver.find_elements(By.CSS_SELECTOR, '[data-testid="loading"]'),
         message="the loading screen is gone once the app runs")
    assert el(driver, "ladder").is_displayed()


def test_a_blocked_app_leaves_the_loading_screen_saying_what_to_do(driver, base_url):
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.setBlockedURLs", {"urls": ["*.wasm"]})
    driver.get(base_url)
    loading = el(driver, "loading")
    assert "Hashigo" in loading.text and "Loading" in loading.text
    late = el(driver, "loading-late")
    assert float(late.value_of_css_property("opacity")) < 0.5, "not at once"
    wait(driver, lambda: float(late.value_of_css_property("opacity")) == 1.0, timeout=30,
         message="after a while it says what to do")
    assert "WebAssembly" in late.text
