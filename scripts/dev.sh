#!/usr/bin/env bash
# Development: `trunk serve` at http://127.0.0.1:8080, rebuilding and
# reloading on every change (an unoptimised build; scripts/serve.sh
# serves the release as users get it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/setup.sh serve
export PATH="$HOME/.cargo/bin:$root/.tools/node_modules/.bin:$PATH"
cargo fetch --locked
exec trunk serve
