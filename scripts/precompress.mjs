// Trunk post-build hook (after no-inline-script.py): writes a `.br` and a
// `.gz` next to each file of the build that compresses, so a static
// server sends them to browsers that accept them (scripts/serve.sh serves
// dist/ with http-server's --brotli --gzip; docs/hosting.md). Brotli at
// its highest level from Node's zlib; gzip by Zopfli (@gfx/zopfli, from
// npm into .tools/ by scripts/setup.sh), which any gzip reader reads and
// which is about 5 % smaller than zlib's best. A few seconds a build.
import { readdirSync, readFileSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { brotliCompressSync, constants } from "node:zlib";

// `trunk serve` rebuilds on every change: nothing to gain there.
if (process.env.TRUNK_PROFILE === "debug") {
  process.exit(0);
}

const root = join(dirname(fileURLToPath(import.meta.url)), "..");
const { gzipAsync } = createRequire(join(root, ".tools", "node_modules", "x.js"))("@gfx/zopfli");
const dir = process.env.TRUNK_STAGING_DIR ?? process.argv[2] ?? "dist";
const worth = /\.(html|js|css|wasm|svg|webmanifest|json)$/;

// The folders too: the start screen and the guide (web/start, web/guide).
for (const entry of readdirSync(dir, { recursive: true, withFileTypes: true })) {
  const path = join(entry.parentPath ?? entry.path, entry.name);
  if (!entry.isFile() || !worth.test(entry.name)) {
    continue;
  }
  const bytes = readFileSync(path);
  writeFileSync(`${path}.gz`, await gzipAsync(bytes, { numiterations: 15 }));
  writeFileSync(
    `${path}.br`,
    brotliCompressSync(bytes, {
      params: {
        [constants.BROTLI_PARAM_QUALITY]: constants.BROTLI_MAX_QUALITY,
        [constants.BROTLI_PARAM_SIZE_HINT]: bytes.length,
      },
    }),
  );
}
