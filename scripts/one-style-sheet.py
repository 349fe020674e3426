#!/usr/bin/env python3
"""Trunk post-build hook: the page's style sheets become one file.

Trunk links each `data-trunk rel="css"` sheet as a file of its own. Over
HTTP/1.1 a browser opens at most six connections to a host, and with
seven sheets, the scripts and the manifest asked for at once, the page's
wasm waited for a free connection: on issue #53's slow link (1.6 Mbit/s,
150 ms) it began to arrive ~250 ms after it was asked for, ~20 ms with
one sheet (docs/performance.md, "One style sheet"). So the sheets are
joined in the order index.html links them (the cascade is unchanged),
their comments and runs of white space dropped (never inside a quoted
string), and written as `style-<hash>.css`, linked where the first of
them was, with its integrity.
"""

import base64
import hashlib
import os
import pathlib
import re
import sys

LINK = re.compile(r'<link rel="stylesheet" href="/([^"/]+\.css)"[^>]*/?>')


def fail(message):
    sys.exit(f"one-style-sheet: {message}")


def squeeze(css):
    """`css` without comments and with each run of white space one space,
    none next to a block's braces or a declaration's end; quoted strings
    are kept as written (an escape such as `\\25CB ` ends at its space)."""
    out = []
    plain = []

    def flush():
        text = re.sub(r"\s+", " ", "".join(plain))
        out.append(re.sub(r" ?([{};]) ?", r"\1", text))
        plain.clear()

    i = 0
    n = len(css)
    while i < n:
        c = css[i]
        if c in "\"'":
            end = i + 1
            while end < n and css[end] != c:
                end += 2 if css[end] == "\\" else 1
            if end >= n:
                fail("a string is not closed")
            flush()
            out.append(css[i:end + 1])
            i = end + 1
        elif css.startswith("/*", i):
            end = css.find("*/", i + 2)
            if end < 0:
                fail("a comment is not closed")
            # A comment between two words still parts them.
            plain.append(" ")
            i = end + 2
        else:
            plain.append(c)
            i += 1
    flush()
    return "".join(out).strip() + "\n"


def join(staging, html):
    """`html` linking one sheet instead of Trunk's several; the sheet is
    written into `staging` and the old ones removed."""
    names = LINK.findall(html)
    if not names:
        return html
    sheets = []
    for name in names:
        path = staging / name
        if not path.is_file():
            fail(f"{name} is linked but not built")
        sheets.append(path.read_text(encoding="utf-8"))
    data = "".join(squeeze(s) for s in sheets).encode()
    name = f"style-{hashlib.sha256(data).hexdigest()[:16]}.css"
    integrity = "sha384-" + base64.b64encode(hashlib.sha384(data).digest()).decode()
    (staging / name).write_bytes(data)
    for old in names:
        (staging / old).unlink()
    first = [True]

    def link(_match):
        if first[0]:
            first[0] = False
            return f'<link rel="stylesheet" href="/{name}" integrity="{integrity}"/>'
        return ""

    return LINK.sub(link, html)


def main():
    staging = pathlib.Path(os.environ.get("TRUNK_STAGING_DIR", sys.argv[1] if len(sys.argv) > 1 else "dist"))
    index = staging / "index.html"
    html = index.read_text(encoding="utf-8")
    index.write_text(join(staging, html), encoding="utf-8")


if __name__ == "__main__":
    main()
