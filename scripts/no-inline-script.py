#!/usr/bin/env python3
"""Trunk post-build hook: moves the loader Trunk writes inline into
index.html to a file of its own, so the page's Content-Security-Policy
can forbid inline scripts (docs/app.md, "Security"); the file is named by
a hash of its content, like Trunk's own files. Then writes the release's
file list and version into the service worker (web/sw.js), so that a new
release caches itself anew."""

import hashlib
import os
import pathlib
import re
import sys

staging = pathlib.Path(os.environ.get("TRUNK_STAGING_DIR", sys.argv[1] if len(sys.argv) > 1 else "dist"))
index = staging / "index.html"
html = index.read_text(encoding="utf-8")
pattern = re.compile(r'<script type="module">(.*?)</script>', re.S)
match = pattern.search(html)
if match is None:
    sys.exit(0)
code = match.group(1).strip() + "\n"
digest = hashlib.sha384(code.encode()).hexdigest()[:16]
name = f"init-{digest}.js"
(staging / name).write_text(code, encoding="utf-8")
html = html[: match.start()] + f'<script type="module" src="/{name}"></script>' + html[match.end():]
index.write_text(html, encoding="utf-8")
if pattern.search(html) or "<script>" in html:
    sys.exit("an inline script is left in index.html")

worker = staging / "sw.js"
if worker.exists():
    files = sorted(p.name for p in staging.iterdir() if p.is_file() and p.name != "sw.js")
    # The start screen (a fresh profile's first screen, and Help's) is kept
    # for offline use with the page; the guide is kept when first read
    # (web/sw.js).
    start = staging / "start"
    if start.is_dir():
        files += sorted(
            str(p.relative_to(staging)) for p in start.rglob("*")
            if p.is_file() and p.suffix not in (".gz", ".br"))
    # Over every file's bytes: the files worker's names carry no hash
    # (Trunk names a worker by its binary), so a name list would miss a
    # change to it.
    digest = hashlib.sha384(html.encode())
    for f in files:
        digest.update(f.encode() + b"\0" + (staging / f).read_bytes())
    version = digest.hexdigest()[:16]
    listed = '", "'.join(["/"] + [f"/{f}" for f in files])
    text = worker.read_text(encoding="utf-8")
    text = text.replace("__VERSION__", version).replace('"__FILES__"', f'"{listed}"')
    worker.write_text(text, encoding="utf-8")
