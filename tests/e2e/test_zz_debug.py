import time
from selenium.webdriver.common.by import By
from test_app import el, wait
from test_ladder import seed_running

def test_debug(driver, base_url):
    seed_running(driver, base_url, "max")
    el(driver, "input-X00").click()
    el(driver, "dock-tab-chart").click()
    time.sleep(3)
    rows = driver.execute_script("return [...document.querySelectorAll('.chart-row')].map(g => g.dataset.testid + ' ' + g.dataset.shape + ' ' + g.dataset.scans)")
    texts = driver.execute_script("return [...document.querySelectorAll('.chart-band-text, .chart-at')].map(e => e.dataset.row + '=' + e.textContent)")
    names = driver.execute_script("return document.querySelector('.chart-names').innerText")
    paths = driver.execute_script("return [...document.querySelectorAll('.chart-row path')].map(p => (p.getAttribute('d')||'').slice(0,80))")
    print(rows, texts, names, paths, driver.execute_script("return document.querySelector('.chart-plot').getBoundingClientRect().width"))
    assert False
