#!/usr/bin/env bash
# Runs every zetafill test on a fresh machine, installing what it needs first.
#   bash scripts/test-all.sh
# Steps: the Cortex-M3 Rust target; the core built and linted for it (no_std, no alloc,
# no panicking constructs); every host test of the workspace in release mode.
set -euo pipefail
cd "$(dirname "$0")/.."

step() { printf '\n== %s\n' "$*"; }

step "installing the Rust target thumbv7m-none-eabi"
rustup target add thumbv7m-none-eabi
rustup component add clippy >/dev/null 2>&1 || true

step "core builds for Cortex-M3 (no_std, no allocator)"
cargo build -p zetafill --target thumbv7m-none-eabi --release

if cargo clippy --version >/dev/null 2>&1; then
    step "core lints: no unwrap/expect/panic/indexing that can panic, on the firmware target"
    cargo clippy -p zetafill --target thumbv7m-none-eabi --release -- -D warnings
    step "workspace lints (libraries and binaries)"
    cargo clippy --workspace --release -- -D warnings
fi

step "host tests (release)"
cargo test --workspace --release
