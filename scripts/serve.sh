#!/usr/bin/env bash
# Installs only what building and serving needs (no browser, no test
# tools), builds the release once and serves dist/ at
# http://127.0.0.1:8080 as a static host would: each file's .br or .gz
# when the browser accepts it (docs/hosting.md). For rebuild-on-change
# while developing, scripts/dev.sh.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/setup.sh serve
export PATH="$HOME/.cargo/bin:$root/.tools/node_modules/.bin:$PATH"
cargo fetch --locked
trunk build --release
port=${PORT:-8080}
echo "Hashigo: http://127.0.0.1:$port"
# -c60: the hashed files could be kept longer; index.html, sw.js and the
# worker's unhashed files must not be (docs/hosting.md says what a real
# host should send).
NODE_OPTIONS=--no-deprecation exec http-server dist -a 127.0.0.1 -p "$port" --brotli --gzip -c60 -s
