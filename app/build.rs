//! The page's wasm keeps its relocations (`--emit-relocs`) so that the
//! build can split it into parts fetched on first use (wasm-split,
//! scripts/split-wasm.sh, docs/performance.md "Parts"). Only the page's
//! own binary: the libraries and the files worker are linked as before.

fn main() {
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.starts_with("wasm32") {
        println!("cargo::rustc-link-arg-bins=--emit-relocs");
    }
}
