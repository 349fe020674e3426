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
import html.parser
import io
import pathlib
import re
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
            # The start screen a fresh profile sees, closed as once used.
            "localStorage.setItem('hashigo.start', 'closed');"
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

    def content_box(self, testid, pad=4, css=None):
        """The box around what the element (or the one `css` selects)
        shows, its innermost elements, cut to the window: a dock's panel
        without the dock's empty rest."""
        element = self.d.find_element(By.CSS_SELECTOR, css) if css else self.el(testid)
        r = self.d.execute_script(
            "const e = arguments[0], o = e.getBoundingClientRect(); let right = o.left, bottom = o.top;"
            "const shows = (c) => /^(INPUT|BUTTON|TEXTAREA|SELECT|IMG|svg|CANVAS)$/.test(c.tagName)"
            "  || [...c.childNodes].some(n => n.nodeType === 3 && n.textContent.trim());"
            "for (const c of e.querySelectorAll('*')) { if (!shows(c)) continue;"
            "  const r = document.createRange(); r.selectNodeContents(c);"
            "  const b = /^(INPUT|BUTTON|TEXTAREA|SELECT|IMG|svg|CANVAS)$/.test(c.tagName)"
            "    ? c.getBoundingClientRect() : r.getBoundingClientRect();"
            "  if (!b.width || !b.height) continue;"
            "  right = Math.max(right, b.right); bottom = Math.max(bottom, b.bottom); }"
            "return [o.left, o.top, Math.min(right, innerWidth), Math.min(bottom, innerHeight)];",
            element)
        return (r[0], r[1], r[2] + pad, r[3] + pad)

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
    p.stack(path, [rung_box(p), p.content_box(None, 8, '[data-dock-panel="watch"]')])


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
    p.stack(path, [rung_box(p), p.content_box("why-panel", 8)])


# The book's test program with its five cases as a share link:
# `hashigo share --program engine/programs/minasec-u/seed-test.json`. (Opened
# with File > Open, the page of this release shows the ladder but not its
# cases; opened as a link, the cases run with the board's settings until
# the link is kept.)
SEED_LINK = (
    "2.lVNNb9NAEHXs2pVa0RaEOACV5gaHdDW7bRpaxAVL_ADwAY5WusarOnbk2YL498zsOhRKe2gO0cybjzfv2U6ytMRUY1rhjl"
    "aa0kqnmvLsK2JOvh49R3qH_LDhwOyvhpvew6qz9Zh9Q9wdb_re9d851k9ibbT1qrVX-dsvMg28Zw4yzpG-BJ6BduiuCJwn2z"
    "Uw9GmWClsmRIUsnaXhP5mpT51bXdsRfrauszBxXUKFEtMEVxocwdA0sywMZiyhYDnJCVe8W1vigTfc0Z9I9h7kwLDDkYVwNA"
    "F7wL8KC9GfFOwJ8z8rg6J17UURdPV6M-OuEuVMneyXt2YwLv4UWYmfkySP1r1AtaC5OKD3UC1jiHvZobjwARBqD6jO6JXkcg"
    "1Lcr51fUCVQnVOr6XG234RaGjGYQ2yCfwABmm3iQY9RPSyurNXc59Smluk1NRd96dkQsmod_Tf1CnfodSpuqDp-TO7xgdIi4"
    "MS1Q-Wp0WeocMpvQgp0gFbtxXP6dG2OwJmW9dTehzqkwEYHTA6GnBGz8ObdW3thpF2eprz-w8zAdQMmoUyMWaPgvn_OhGMWP"
    "DHcHxr_pZa4EC-vHv6OeXhVfj4GHoT6kbQZUQNo-nTaXXcvGTOo79tk9bf"
)


def tests(p, path):
    p.d.get(p.url + "#" + SEED_LINK)
    p.wait(lambda: p.d.find_elements(By.CSS_SELECTOR, '[data-kind="coil"][data-device="C0R"]'), "the link opens")
    time.sleep(1)
    p.click("shared-keep", 1.0)  # its settings (the book's pots and preset) apply only once kept
    p.tab("tests")
    p.click("run-tests", 3.0)
    p.wait(lambda: p.el("tests-summary").text.strip().startswith("5"), "the book's five cases run")
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
    p.crop(path, box=p.content_box(None, 8, '[data-dock-panel="listing"]'))


def cpu(p, path):
    p.example("seed-test")
    p.tab("cpu")
    p.click("cpu-view-open", 0.5)
    for _ in range(3):  # a few edges in, so that blocks are lit
        p.click("cpu-step-edge", 0.2)
    p.crop(path, box=p.box("cpu-view", 2))


def machine_panel(machine, example, press):
    """The machine's panel running its example, the inputs `press`
    (testid prefixes: the first element matching each) switched on."""
    def scene(p, path):
        p.machine(machine)
        if example:
            p.example(example)
        p.click("run", 1.2)
        for prefix in press:
            p.d.find_element(By.CSS_SELECTOR, f'[data-testid^="{prefix}"]').click()
            time.sleep(0.4)
        time.sleep(0.8)
        p.crop(path, box=p.content_box("dock-right"))
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
    ("cpu", True, cpu, 640),
    ("io86a", True, machine_panel("io86a", "timer", ["io86a-input-X00"]), None),
    ("avr-plc", True, machine_panel("avr-plc", "self-hold", ["avr-input-R4.0", "avr-input-R4.1"]), None),
    ("arduino-plc", True, machine_panel("arduino-plc", "self-hold", ["arduino-input-X000"]), None),
    ("soft-plc", True, machine_panel("soft-plc", "parts", ["soft-input-IX0-0"]), None),
]


# The sections the page's panes link to, in both languages.
SECTION_IDS = ["start", "drawing", "running", "forcing", "stepping", "time-travel", "watch", "chart", "why",
               "tests", "sharing", "files", "listing", "variables", "program", "cpu", "machines",
               "minasec-u", "io86a", "avr-plc", "arduino-plc", "soft-plc"]


class Fragment(html.parser.HTMLParser):
    """What the check needs from a guide file: ids, links, images, and
    anything the page's CSP or its guide panel would not take."""

    def __init__(self):
        super().__init__()
        self.ids, self.links, self.images, self.bad, self.roots = [], [], [], [], []
        self.depth = 0

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if self.depth == 0:
            self.roots.append((tag, a.get("class"), a.get("lang")))
        if tag not in ("img", "br", "hr"):
            self.depth += 1
        if tag in ("script", "style", "html", "head", "body", "iframe"):
            self.bad.append(f"<{tag}>")
        self.bad += [f"{name}= on <{tag}>" for name in a if name == "style" or name.startswith("on")]
        if "id" in a:
            self.ids.append(a["id"])
        if tag == "a" and a.get("href", "").startswith("#"):
            self.links.append(a["href"][1:])
        if tag == "img":
            self.images.append(a)

    def handle_endtag(self, tag):
        self.depth -= 1


def check_guide(fix_sizes=False):
    """Checks web/guide/{en,ja}.html (one root article, the sections' ids,
    the same ids in both, links that land, no inline script or style, each
    picture there with its alt, width and height); with fix_sizes, writes
    each picture's real size into its width and height first."""
    problems = []
    ids = {}
    for lang in ["en", "ja"]:
        path = ROOT / "web" / "guide" / f"{lang}.html"
        text = path.read_text()
        if fix_sizes:
            def sized(m):
                file = ROOT / "web" / m.group(2)
                if not file.exists():
                    return m.group(0)
                w, h = Image.open(file).size
                return f'{m.group(1)}width="{w}" height="{h}"'
            text = re.sub(r'(<img src="(guide/img/[^"]+)" alt="[^"]*" )width="\d+" height="\d+"', sized, text)
            path.write_text(text)
        f = Fragment()
        f.feed(text)
        if f.roots != [("article", "guide-doc", lang)]:
            problems.append(f"{lang}: one root <article class=guide-doc lang={lang}>, not {f.roots}")
        problems += [f"{lang}: {b}" for b in f.bad]
        problems += [f"{lang}: no section #{i}" for i in SECTION_IDS if i not in f.ids]
        problems += [f"{lang}: #{i} twice" for i in set(f.ids) if f.ids.count(i) > 1]
        # A share link (an exercise) is written `./#2.…`, so the guide's panel,
        # which scrolls to `#section` links, leaves it to the page.
        problems += [f"{lang}: a link to #{i}, which is not there" for i in f.links
                     if i not in f.ids and not re.match(r"\d+\.", i)]
        if "guide-toc" not in text:
            problems.append(f"{lang}: no nav.guide-toc")
        for img in f.images:
            file = ROOT / "web" / img.get("src", "")
            if not img.get("src", "").startswith("guide/img/") or not file.exists():
                problems.append(f"{lang}: no picture {img.get('src')}")
            elif (int(img.get("width", 0)), int(img.get("height", 0))) != Image.open(file).size:
                problems.append(f"{lang}: {img['src']} is {Image.open(file).size}, not its width and height")
            if not img.get("alt"):
                problems.append(f"{lang}: {img.get('src')} has no alt")
        ids[lang] = f.ids
    if ids["en"] != ids["ja"]:
        problems.append("en and ja do not have the same ids in the same order")
    return problems


def main():
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--url", default="http://127.0.0.1:8150/")
    args.add_argument("--only", default="", help="comma-separated scene names (workbench for the README's)")
    args.add_argument("--check", action="store_true", help="only check the guide's files, take no picture")
    args = args.parse_args()
    if args.check:
        problems = check_guide()
        for problem in problems:
            print(problem, file=sys.stderr)
        return 1 if problems else 0
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
    failed += check_guide(fix_sizes=True)
    for f in failed:
        print("failed:", f, file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
