#!/usr/bin/env python3
"""The guide's pictures (web/guide/img/) and the README's screenshot
(docs/img/workbench.png), taken from the real page.

Usage (from the repository's root; a release build in dist/ or given):

    cd dist && python3 -m http.server 8150 &      # or scripts/serve.sh
    .tools/venv/bin/python scripts/guide-pictures.py [--url http://127.0.0.1:8150/] [--only NAME,...]

Needs Selenium, Chromium at /usr/bin/chromium with /usr/bin/chromedriver
(scripts/setup.sh installs them) and Pillow (`pip install Pillow`) for the
crops and the palette reduction that keeps web/guide/ small.

Each picture is one scene: a fresh profile (empty storage, the interface's
language set), the page at 1366x768 (390x844 with touch for the phone's),
a few steps done as a user would (keys, clicks), then the screen cropped to
the elements the guide's section is about. A picture with words on it is
taken twice, `NAME-en.png` with the English interface and `NAME-ja.png`
with the Japanese one; a picture without words once, `NAME.png`. The PNGs
are reduced to a 64-colour palette (the page's flat colours survive it).
"""

import argparse
import io
import pathlib
import sys
import time

from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

ROOT = pathlib.Path(__file__).resolve().parents[1]
GUIDE_IMG = ROOT / "web" / "guide" / "img"
DOCS_IMG = ROOT / "docs" / "img"
COLOURS = 64


class Page:
    """One browser on the page, at a given size and language."""

    def __init__(self, url, lang, width=1366, height=768, phone=False, docks=None):
        options = webdriver.ChromeOptions()
        options.binary_location = "/usr/bin/chromium"
        for flag in ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--disable-background-networking", "--no-first-run", "--hide-scrollbars",
                     "--lang=en-US", f"--window-size={width},{height + 200}"]:
            options.add_argument(flag)
        if phone:
            options.add_experimental_option("mobileEmulation", {
                "deviceMetrics": {"width": width, "height": height, "pixelRatio": 1, "touch": True}})
        self.d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
        if not phone:
            # The viewport exactly width x height (the window's own size
            # includes the browser's frame).
            self.d.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
                "width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
        self.url = url
        self.d.get(url)
        self.d.execute_script(
            "localStorage.clear(); localStorage.setItem('hashigo.lang', arguments[0]);"
            "if (arguments[1]) localStorage.setItem('hashigo.docks', arguments[1]);", lang, docks)
        self.d.get(url)
        self.wait(lambda: self.find("run"), "the page mounts")
        time.sleep(1)

    def wait(self, condition, message="", timeout=20):
        return WebDriverWait(self.d, timeout, poll_frequency=0.05).until(lambda _: condition(), message)

    def find(self, testid):
        found = self.d.find_elements(By.CSS_SELECTOR, f'[data-testid="{testid}"]')
        return found[0] if found else None

    def el(self, testid):
        found = self.find(testid)
        if found is None:
            raise RuntimeError(f"no [data-testid={testid}]")
        return found

    def click(self, testid, pause=0.3):
        self.el(testid).click()
        time.sleep(pause)

    def keys(self, *keys):
        ActionChains(self.d).send_keys(*keys).perform()
        time.sleep(0.15)

    def place(self, key, device, shift=False):
        """F5/F6/F7 (with Shift: an OR branch), the device, Enter."""
        if shift:
            ActionChains(self.d).key_down(Keys.SHIFT).send_keys(key).key_up(Keys.SHIFT).perform()
        else:
            self.keys(key)
        self.wait(lambda: self.d.switch_to.active_element.get_attribute("data-testid") == "device-input",
                  "the device entry opens")
        self.keys(device, Keys.ENTER)
        self.wait(lambda: self.d.switch_to.active_element.get_attribute("data-testid") == "ladder",
                  f"{device} placed")

    def machine(self, machine):
        Select(self.el("machine")).select_by_value(machine)
        self.wait(lambda: self.el("workbench").get_attribute("data-machine") == machine, machine)
        time.sleep(0.5)

    def example(self, value):
        self.click("menu-file")
        Select(self.el("example")).select_by_value(value)
        time.sleep(0.8)
        self.keys(Keys.ESCAPE)

    def self_hold(self, no="X00", nc="X01", coil="Y00"):
        """The start/stop self-hold: NO start, NC stop, the coil, and the
        coil's own contact in parallel with start."""
        self.click("new-ladder")
        self.click("cell-0-0-0")
        self.place(Keys.F5, no)
        self.place(Keys.F6, nc)
        self.place(Keys.F7, coil)
        self.keys(Keys.ARROW_UP)
        self.place(Keys.F5, coil, shift=True)

    def tab(self, tool):
        self.click(f"dock-tab-{tool}", 0.5)

    def crop(self, path, testids=(), pad=6, box=None):
        """The union of the elements' boxes and `box` (left, top, right,
        bottom in CSS px) cut from the screen, reduced, written to `path`."""
        rects = [[v - pad if i < 2 else v + pad for i, v in enumerate(self.d.execute_script(
            "const r = arguments[0].getBoundingClientRect();"
            "return [r.left, r.top, r.right, r.bottom];", self.el(t)))] for t in testids]
        if box is not None:
            rects.append(box)
        box = (min(r[0] for r in rects), min(r[1] for r in rects),
               max(r[2] for r in rects), max(r[3] for r in rects))
        shot = Image.open(io.BytesIO(self.d.get_screenshot_as_png())).convert("RGB")
        scale = shot.width / self.d.execute_script("return innerWidth")
        left, top, right, bottom = (max(0, round(v * scale)) for v in box)
        save(shot.crop((left, top, min(right, shot.width), min(bottom, shot.height))), path)

    def box(self, testid, pad=6):
        """The element's box (CSS px), cut to the window."""
        r = self.d.execute_script(
            "const r = arguments[0].getBoundingClientRect();"
            "return [r.left, r.top, Math.min(r.right, innerWidth), Math.min(r.bottom, innerHeight)];",
            self.el(testid))
        return (r[0] - pad, r[1] - pad, r[2] + pad, r[3] + pad)

    def stack(self, path, boxes, gap=8):
        """Several boxes of the screen, one under the other, as one picture."""
        shot = Image.open(io.BytesIO(self.d.get_screenshot_as_png())).convert("RGB")
        scale = shot.width / self.d.execute_script("return innerWidth")
        parts = [shot.crop(tuple(max(0, round(v * scale)) for v in b)) for b in boxes]
        out = Image.new("RGB", (max(p.width for p in parts), sum(p.height for p in parts) + gap * (len(parts) - 1)),
                        (250, 250, 248))
        y = 0
        for part in parts:
            out.paste(part, (0, y))
            y += part.height + gap
        save(out, path)

    def quit(self):
        self.d.quit()


def save(image, path, colours=COLOURS):
    """A PNG reduced to a palette (what keeps the guide's pictures small)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    image.quantize(colors=colours, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(
        path, optimize=True)
    print(f"{path.relative_to(ROOT)}: {image.width}x{image.height}, {path.stat().st_size} bytes")


def running_self_hold(p):
    """The self-hold drawn, run, X00 pressed and released: Y00 latched."""
    p.self_hold()
    p.click("run", 1.0)
    p.click("input-X00", 0.6)
    p.click("input-X00", 0.8)


# Each scene: (name, has words, function(page, path)).
def workbench(p, path):
    running_self_hold(p)
    save(Image.open(io.BytesIO(p.d.get_screenshot_as_png())).convert("RGB"), path, 128)


def first_rung(p, path):
    running_self_hold(p)
    p.click("cell-1-0-0")
    p.crop(path, box=rung_box(p))


def palette(p, path):
    p.crop(path, ["palette", "palette-search"], pad=4)


def run_controls(p, path):
    running_self_hold(p)
    p.crop(path, ["run", "pause", "step-scan", "step-instr", "step-clock", "speed", "sim-time"], pad=6)


def panel(p, path):
    running_self_hold(p)
    p.crop(path, [f"input-X0{i}" for i in range(8)] + [f"lamp-Y0{i}" for i in range(8)], pad=30)


def phone_strip(p, path):
    p.click("new-ladder")
    p.click("cell-0-0-0")
    for item, device in [("palette-no", "X00"), ("palette-nc", "X01"), ("palette-coil", "Y00")]:
        p.click(item)
        chips = p.wait(lambda: [b for b in p.d.find_elements(
            By.CSS_SELECTOR, '[data-testid="device-options"] button') if b.text.split()[0] == device], device)
        chips[0].click()
        p.click("device-ok", 0.4)
    p.click("run", 1.0)
    p.click("strip-in-X00", 0.8)
    p.crop(path, ["io-strip"], pad=4, box=rung_box(p, rows=1))


def watch_forces(p, path):
    running_self_hold(p)
    p.tab("watch")
    for device in ["Y00", "X00", "X01"]:
        p.el("watch-input").send_keys(device)
        p.click("watch-add", 0.2)
    p.el("cell-0-0-0").click()  # X00's contact: held on from the ladder
    time.sleep(0.8)
    p.stack(path, [rung_box(p), p.box("dock-bottom", 0)])


def travel(p, path):
    running_self_hold(p)
    p.click("input-X01", 0.5)
    p.click("input-X01", 0.5)
    p.click("pause", 0.5)
    p.el("timeline").send_keys(Keys.PAGE_DOWN)  # back to a scan while Y00 still ran
    time.sleep(0.3)
    while p.el("rung-0").find_elements(By.CSS_SELECTOR, '[data-kind="coil"][data-powered="0"]'):
        p.click("step-back", 0.1)
    for _ in range(5):  # a few scans into the latch, not the scan the stop was read in
        p.click("step-back", 0.1)
    p.stack(path, [p.box("travel-bar", 4), rung_box(p)])


def chart(p, path):
    running_self_hold(p)
    for device in ["X01", "X00"] * 2:
        p.click(f"input-{device}", 0.5)
        p.click(f"input-{device}", 0.7)
    p.click("pause", 0.3)
    p.tab("chart")
    time.sleep(0.8)
    p.crop(path, box=p.box("timing-chart", 4))


def why(p, path):
    p.self_hold()
    p.click("run", 1.0)
    p.d.find_element(By.CSS_SELECTOR, '[data-testid="ladder"] [data-kind="coil"]').click()
    time.sleep(0.3)
    p.keys("w")
    p.tab("why")
    time.sleep(0.8)
    p.stack(path, [rung_box(p), p.box("why-panel", 4)])


def tests(p, path):
    p.example("seed-test")
    p.tab("tests")
    p.click("run-tests", 3.0)
    p.wait(lambda: "5" in p.el("tests-summary").text, "the book's five cases run")
    p.crop(path, box=p.box("dock-bottom", 0))


def rung_box(p, rung=0, rows=2):
    """Rung `rung`'s label, its first `rows` rows, rail to rail (its
    empty right part left out)."""
    r = p.d.execute_script(
        "const b = (id) => document.querySelector('[data-testid=\"' + id + '\"]').getBoundingClientRect();"
        "const rung = b(arguments[0]), last = b(arguments[1]), low = b(arguments[2]);"
        "return [rung.left, rung.top, last.right, low.bottom];",
        f"rung-{rung}", f"cell-{rung}-0-9", f"cell-{rung}-{rows - 1}-0")
    return (r[0] - 2, r[1] - 2, r[2] + 8, r[3] + 4)


def listing(p, path):
    p.self_hold()
    p.tab("listing")
    time.sleep(0.5)
    p.crop(path, box=p.box("dock-bottom", 0))


def cpu(p, path):
    p.example("seed-test")
    p.tab("cpu")
    time.sleep(0.5)
    p.crop(path, box=p.box("cpu-view", 2))


def machine_panel(machine, example):
    def scene(p, path):
        p.machine(machine)
        if example:
            p.example(example)
        p.click("run", 1.2)
        p.crop(path, box=p.box("dock-right", 0))
    return scene


# (name, words on it, the scene, the bottom dock's height: None for the default)
SCENES = [
    ("first-rung", True, first_rung, None),
    ("palette", True, palette, None),
    ("run-controls", True, run_controls, None),
    ("panel", True, panel, None),
    ("phone-strip", True, phone_strip, None),
    ("watch", True, watch_forces, None),
    ("travel", True, travel, None),
    ("chart", True, chart, 330),
    ("why", True, why, 300),
    ("tests", True, tests, 430),
    ("listing", True, listing, 300),
    ("cpu", True, cpu, 560),
    ("io86a", True, machine_panel("io86a", "timer"), None),
    ("avr-plc", True, machine_panel("avr-plc", "self-hold"), None),
    ("arduino-plc", True, machine_panel("arduino-plc", "self-hold"), None),
    ("soft-plc", True, machine_panel("soft-plc", "parts"), None),
]


def main():
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--url", default="http://127.0.0.1:8150/")
    args.add_argument("--only", default="", help="comma-separated scene names (workbench for the README's)")
    args = args.parse_args()
    only = set(filter(None, args.only.split(",")))
    failed = []
    jobs = [("workbench", None, workbench, DOCS_IMG / "workbench.png", False, None)]
    for name, words, scene, bottom in SCENES:
        phone = name.startswith("phone")
        docks = f"400,{bottom},1,1,watch" if bottom else None
        for lang in (["en", "ja"] if words else ["en"]):
            file = f"{name}-{lang}.png" if words else f"{name}.png"
            jobs.append((name, lang, scene, GUIDE_IMG / file, phone, docks))
    for name, lang, scene, path, phone, docks in jobs:
        if only and name not in only:
            continue
        page = Page(args.url, lang or "en", *((390, 844) if phone else (1366, 768)), phone=phone, docks=docks)
        try:
            scene(page, path)
        except Exception as e:  # one scene's failure is reported, the others are still taken
            failed.append(f"{path.name}: {e}")
        finally:
            page.quit()
    for f in failed:
        print("failed:", f, file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
