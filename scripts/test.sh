#!/usr/bin/env bash
# Installs whatever is missing, then runs every test and check:
# formatting, clippy on native and wasm32, the engine's native tests, the
# engine's wasm32 build, and (when the app is present) the app's browser
# tests and the end-to-end tests.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/setup.sh
export PATH="$HOME/.cargo/bin:$root/.tools/node_modules/.bin:$PATH"

step() { printf '\n==> %s\n' "$*"; }

step "cargo fmt --check"
cargo fmt --all -- --check

step "clippy, native"
cargo clippy --workspace --all-targets --locked -- -D warnings

step "clippy, wasm32 (the engine without its CLI)"
cargo clippy -p engine --lib --no-default-features --target wasm32-unknown-unknown --locked -- -D warnings

step "engine tests (native)"
cargo test -p engine --locked

step "engine builds for wasm32"
cargo build -p engine --lib --no-default-features --target wasm32-unknown-unknown --release --locked

if [ -d app ]; then
  step "app logic tests (native: pacing, storage validation) and the files worker's"
  cargo test -p app --lib --locked
  cargo test -p files_worker --locked

  step "clippy, wasm32 (the app and its files worker)"
  cargo clippy -p app -p files_worker --all-targets --target wasm32-unknown-unknown --locked -- -D warnings

  step "app tests in headless Chromium (wasm-pack)"
  wasm-pack test --headless --chrome --mode no-install app

  step "end-to-end tests"
  bash scripts/e2e.sh
fi

printf '\nall checks passed\n'
