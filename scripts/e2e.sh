#!/usr/bin/env bash
# End-to-end tests: builds the release dist/ and the native hashigo, then
# drives Debian's Chromium through ChromeDriver (Selenium, pytest) against
# dist/ served on 127.0.0.1. Artefacts (screenshot, figures) go to
# tests/e2e/artifacts/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
export PATH="$HOME/.cargo/bin:$root/.tools/node_modules/.bin:$PATH"

venv="$root/.tools/venv"
if [ ! -x "$venv/bin/pytest" ] || ! "$venv/bin/python" -c "import selenium" 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check -r tests/e2e/requirements.txt
fi

cargo fetch --locked
trunk build --release
cargo build --release --locked -p engine --bin hashigo
mkdir -p tests/e2e/artifacts
"$venv/bin/pytest" -q tests/e2e
