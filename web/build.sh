#!/usr/bin/env bash
# Builds the browser page into web/dist/, installing what it needs first:
#   bash web/build.sh
# The wasm32-unknown-unknown Rust target (rustup), binaryen (npm) and wasm-bindgen-cli (cargo, from crates.io) at
# exactly the version of the wasm-bindgen crate in Cargo.lock. Serve the result with any static
# file server, for example: python3 -m http.server -d web/dist 8000
set -euo pipefail
cd "$(dirname "$0")/.."

rustup target add wasm32-unknown-unknown

# The bindings generator must match the wasm-bindgen crate exactly.
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
if [ "$(wasm-bindgen --version 2>/dev/null || true)" != "wasm-bindgen $version" ]; then
    # --locked first; the registry may lack one of the versions its lock file names, and then
    # the newest compatible versions are taken.
    cargo install wasm-bindgen-cli --version "=$version" --locked ||
        cargo install wasm-bindgen-cli --version "=$version"
fi

# The `web` profile (Cargo.toml): the release build optimised for size, with link-time
# optimisation; the page's test checks its files against the CLI's, byte for byte. Two
# modules, each built alone so that their features stay apart: the page (everything but a
# PNG's pixels) and the PNG renderer it loads when a PNG is first asked for.
cargo build --profile web -p zetafill-web --target wasm32-unknown-unknown
cargo build --profile web -p zetafill-web-png --target wasm32-unknown-unknown
target_dir=$(cargo metadata --format-version 1 --no-deps | sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')

rm -rf web/dist
mkdir -p web/dist
for module in zetafill_web zetafill_web_png; do
    wasm-bindgen --target web --no-typescript --out-dir web/dist \
        "$target_dir/wasm32-unknown-unknown/web/$module.wasm"
done
# binaryen's wasm-opt (npm, pinned in web/package.json) shrinks the code, repeating its passes
# until they gain nothing more, and drops the names section; it keeps the semantics exactly (no
# fast-math), so every file stays the CLI's. It may assume what holds for Rust's code: memory
# starts zeroed, its first 1 KiB is never read (the stack lies below the data, from the top of
# the first megabyte down), and no load or store traps (every access is in bounds).
(cd web && npm ci --no-audit --no-fund --silent)
for module in zetafill_web zetafill_web_png; do
    web/node_modules/.bin/wasm-opt -Oz --converge --strip-debug --strip-producers \
        --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext --enable-mutable-globals \
        --low-memory-unused --zero-filled-memory --ignore-implicit-traps --gufa-optimizing \
        "web/dist/${module}_bg.wasm" -o "web/dist/${module}_bg.wasm"
done
cp web/static/* web/dist/
# The built-in font is fetched by the page when a text region asks for it, not embedded.
cp cli/assets/fonts/DejaVuSans-Bold.ttf cli/assets/fonts/DejaVu-LICENSE.txt web/dist/
echo "built web/dist/ ($(du -sh web/dist | cut -f1)); serve it with: python3 -m http.server -d web/dist 8000"
