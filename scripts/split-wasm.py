#!/usr/bin/env python3
"""Trunk post-build hook: splits the page's wasm into the first screen and
the parts fetched on first use (issue #53, docs/performance.md "Parts").

Trunk has no step between cargo and wasm-bindgen (trunk-rs/trunk#1022),
so this hook starts again from cargo's linked wasm (built with
`--emit-relocs`, app/build.rs) and does what Trunk did, split first:

1. wasm-split-cli (crate wasm_split_cli_support, scripts/setup.sh) cuts
   every `#[wasm_split(part)]` function (app/src/parts.rs) into
   `split_<part>.wasm` and writes `__wasm_split.js`, the loader the main
   wasm imports to fetch them;
2. wasm-bindgen on the main wasm, as Trunk runs it;
3. wasm-opt -Oz on every wasm and terser on the main js and the loader
   (release only, as Trunk's own wasm-opt; terser halves the two scripts
   the first screen waits for: ~4 KB of 17 KB gzip, docs/performance.md);
4. each file is named by a hash of its content, and Trunk's staged
   `app-*.js` / `app-*_bg.wasm` are replaced: index.html's references and
   their `integrity` hashes follow.

Runs before scripts/no-inline-script.py, whose file list (the service
worker's cache) then holds the parts too. A debug build is split as
well: the split functions import their loader, which an unsplit wasm
would lack.
"""

import base64
import hashlib
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
BIN = "app"


def fail(message):
    sys.exit(f"split-wasm: {message}")


def tool(name):
    """The project's own copy first (.tools/, scripts/setup.sh), else PATH."""
    local = ROOT / ".tools" / "node_modules" / ".bin" / name
    if local.exists():
        return str(local)
    found = shutil.which(name) or shutil.which(name, path=str(pathlib.Path.home() / ".cargo" / "bin"))
    if found is None:
        fail(f"{name} is missing: run scripts/setup.sh")
    return found


def run(*args):
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        fail(f"{' '.join(args)} failed:\n{done.stdout}{done.stderr}")


def short_hash(data):
    return hashlib.sha256(data).hexdigest()[:16]


def sri(data):
    return "sha384-" + base64.b64encode(hashlib.sha384(data).digest()).decode()


def cargo_wasm(release):
    """The linked wasm cargo just built for Trunk (the `web` profile for a
    release: index.html's data-cargo-profile-release)."""
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    wasm = target / "wasm32-unknown-unknown" / ("web" if release else "debug") / f"{BIN}.wasm"
    if not wasm.exists():
        fail(f"{wasm} is missing")
    return wasm


def split(wasm, work, release):
    """Steps 1-3 in `work`; returns the main js, the main wasm and the parts."""
    data = wasm.read_bytes()
    stem = f"{BIN}-{short_hash(data)}"
    run(tool("wasm-split-cli"), "--target", "web", "--out-name", stem, str(wasm), str(work))
    run(tool("wasm-bindgen"), "--target=web", f"--out-dir={work / 'bg'}", f"--out-name={stem}",
        "--no-typescript", "--keep-lld-exports", str(work / f"{stem}.wasm"))
    main_wasm = work / "bg" / f"{stem}_bg.wasm"
    parts = sorted(work.glob("split_*.wasm")) + sorted(work.glob("chunk_*.wasm"))
    if release:
        for w in [main_wasm] + parts:
            run(tool("wasm-opt"), "-Oz", str(w), "-o", str(w))
    return work / "bg" / f"{stem}.js", main_wasm, parts


def minified(js):
    """`js` (an ES module) as terser compresses and mangles it: its
    exports and property names are kept, so the wasm's imports still
    find their functions."""
    done = subprocess.run([tool("terser"), "--module", "--compress", "--mangle"],
                          input=js, capture_output=True, text=True)
    if done.returncode != 0 or not done.stdout.strip():
        fail(f"terser failed:\n{done.stderr}")
    return done.stdout


def name_parts(work, main_js, parts, staging, release):
    """Parts and the loader get hashed names in `staging`; the main js
    imports the loader by its new name (both minified for a release)."""
    loader = (work / "__wasm_split.js").read_text(encoding="utf-8")
    for part in parts:
        data = part.read_bytes()
        name = f"{part.stem}-{short_hash(data)}.wasm"
        old = f'"./{part.name}"'
        if old not in loader:
            fail(f"{part.name} is not named in __wasm_split.js")
        loader = loader.replace(old, f'"./{name}"')
        (staging / name).write_bytes(data)
    if release:
        loader = minified(loader)
    loader_name = f"__wasm_split-{short_hash(loader.encode())}.js"
    (staging / loader_name).write_text(loader, encoding="utf-8")
    js = main_js.read_text(encoding="utf-8")
    specifier = 'from "./__wasm_split.js"'
    if specifier not in js:
        fail("the main js does not import __wasm_split.js")
    # Only the imports' paths (wasm-bindgen writes one import per group
    # of the loader's functions): the imports object keeps the wasm's own
    # module name as its key.
    js = js.replace(specifier, f'from "./{loader_name}"')
    return minified(js) if release else js


def replace_staged(staging, html, old, new, data):
    """Trunk's staged file `old` gives way to `new` (content `data`)."""
    (staging / old).unlink()
    (staging / new).write_bytes(data)
    html = html.replace(f"/{old}", f"/{new}")
    link = re.compile(r'(<link[^>]*href="/' + re.escape(new) + r'"[^>]*integrity=")([^"]*)(")')
    return link.sub(lambda m: m.group(1) + sri(data) + m.group(3), html)


def main():
    staging = pathlib.Path(os.environ.get("TRUNK_STAGING_DIR", sys.argv[1] if len(sys.argv) > 1 else "dist"))
    release = os.environ.get("TRUNK_PROFILE", "release") == "release"
    index = staging / "index.html"
    html = index.read_text(encoding="utf-8")
    staged_js = re.search(rf"/({BIN}-[0-9a-f]+\.js)", html)
    staged_wasm = re.search(rf"/({BIN}-[0-9a-f]+_bg\.wasm)", html)
    if staged_js is None or staged_wasm is None:
        fail("Trunk's app js or wasm is not named in index.html")
    with tempfile.TemporaryDirectory(prefix="hashigo-split-") as tmp:
        work = pathlib.Path(tmp)
        main_js, main_wasm, parts = split(cargo_wasm(release), work, release)
        js = name_parts(work, main_js, parts, staging, release)
        wasm_data = main_wasm.read_bytes()
        stem = main_js.stem
        html = replace_staged(staging, html, staged_wasm.group(1), f"{stem}_bg.wasm", wasm_data)
        html = replace_staged(staging, html, staged_js.group(1), f"{stem}.js", js.encode())
    index.write_text(html, encoding="utf-8")


if __name__ == "__main__":
    main()
