#!/usr/bin/env bash
# Installs whatever is missing, then builds and serves the app at
# http://127.0.0.1:8080 (rebuilding on change).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/setup.sh
export PATH="$HOME/.cargo/bin:$root/.tools/node_modules/.bin:$PATH"
cargo fetch --locked
exec trunk serve --release
