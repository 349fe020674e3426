#!/usr/bin/env bash
# Installs whatever this project's build and tests need and is missing.
# `setup.sh serve` installs only what building and serving the page needs
# (scripts/serve.sh): no browser, no wasm-pack, no test tools.
# Idempotent: every step checks first, so a second run takes seconds.
# Sources: crates.io, Debian's packages and the npm registry only.
set -euo pipefail

for_tests=yes
[ "${1:-}" = serve ] && for_tests=no

TRUNK_VERSION=0.21.14
WASM_BINDGEN_VERSION=0.2.130 # must equal the wasm-bindgen pin in app/Cargo.toml
WASM_SPLIT_VERSION=0.2.4 # wasm_split_cli_support: splits the page's wasm (scripts/split-wasm.py)
WASM_PACK_VERSION=0.15.1
BINARYEN_VERSION=132.0.0
AXE_VERSION=4.11.0
HTTP_SERVER_VERSION=14.1.1
ZOPFLI_VERSION=1.0.15
TERSER_VERSION=5.51.4

root=$(cd "$(dirname "$0")/.." && pwd)
export PATH="$HOME/.cargo/bin:$root/.tools/node_modules/.bin:$PATH"

say() { printf '[setup] %s\n' "$*" >&2; }

has_version() { # has_version CMD VERSION: CMD --version prints VERSION
  command -v "$1" >/dev/null 2>&1 && "$1" --version 2>/dev/null | grep -qF "$2"
}

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  say "adding the wasm32-unknown-unknown target"
  rustup target add wasm32-unknown-unknown
fi

if ! has_version trunk "$TRUNK_VERSION"; then
  say "installing trunk $TRUNK_VERSION"
  cargo install --locked trunk --version "$TRUNK_VERSION"
fi

if ! has_version wasm-bindgen "$WASM_BINDGEN_VERSION"; then
  say "installing wasm-bindgen-cli $WASM_BINDGEN_VERSION"
  # Not --locked: the crate's own lock file names a version crates.io lacks.
  cargo install wasm-bindgen-cli --version "$WASM_BINDGEN_VERSION" --force
fi

# wasm-split-cli has no --version: cargo's list of installed crates says.
if ! cargo install --list | grep -qF "wasm_split_cli_support v$WASM_SPLIT_VERSION:"; then
  say "installing wasm-split-cli $WASM_SPLIT_VERSION"
  cargo install --locked wasm_split_cli_support --version "$WASM_SPLIT_VERSION" --features build-binary
fi

if ! has_version wasm-opt "version $BINARYEN_VERSION" && ! has_version wasm-opt "version ${BINARYEN_VERSION%%.*}"; then
  say "installing binaryen $BINARYEN_VERSION from npm into .tools/"
  mkdir -p "$root/.tools"
  npm install --prefix "$root/.tools" --no-audit --no-fund "binaryen@$BINARYEN_VERSION" >&2
fi

# http-server serves dist/ with the build's .br / .gz (scripts/serve.sh,
# the end-to-end tests); Zopfli writes the .gz (scripts/precompress.mjs);
# terser minifies the page's two first scripts (scripts/split-wasm.py).
npm_tool() { # npm_tool PACKAGE VERSION: into .tools/ unless there
  if [ ! -f "$root/.tools/node_modules/$1/package.json" ] \
    || ! grep -q "\"version\": \"$2\"" "$root/.tools/node_modules/$1/package.json"; then
    say "installing $1 $2 from npm into .tools/"
    mkdir -p "$root/.tools"
    npm install --prefix "$root/.tools" --no-audit --no-fund "$1@$2" >&2
  fi
}
npm_tool http-server "$HTTP_SERVER_VERSION"
npm_tool @gfx/zopfli "$ZOPFLI_VERSION"
npm_tool terser "$TERSER_VERSION"

if [ "$for_tests" = no ]; then
  say "tools for serving ready"
  exit 0
fi

if ! has_version wasm-pack "$WASM_PACK_VERSION"; then
  say "installing wasm-pack $WASM_PACK_VERSION"
  cargo install --locked wasm-pack --version "$WASM_PACK_VERSION"
fi

# axe-core: the accessibility checks of the end-to-end tests (issue #27).
npm_tool axe-core "$AXE_VERSION"

if [ ! -x /usr/bin/chromium ] || [ ! -x /usr/bin/chromedriver ]; then
  say "installing Debian's chromium and chromium-driver"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >&2
  apt-get install -y -qq chromium chromium-driver >&2
fi

say "tools ready"
