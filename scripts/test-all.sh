#!/usr/bin/env bash
# Runs every zetafill test on a fresh machine, installing what it needs first.
#   bash scripts/test-all.sh
# Steps: the Cortex-M3 Rust target, qemu-system-arm, defmt-print and the glTF validator (npm); the core built and linted
# for it (no_std, no alloc, no panicking constructs); the API docs; the firmware run under QEMU; the browser page
# built (web/build.sh) and driven in headless Chromium against the CLI's files; every host test of the workspace in
# release mode (including host-vs-firmware parity).
set -euo pipefail
cd "$(dirname "$0")/.."

# Each step prints its time when the next begins; a failing step is named; the host tests end
# with a count of passed, failed and ignored tests.
step_name=""
step_start=$SECONDS
end_step() {
    if [ -n "$step_name" ]; then printf -- '-- %s: %ds\n' "$step_name" $((SECONDS - step_start)); fi
}
step() {
    end_step
    step_name="$*"
    step_start=$SECONDS
    printf '\n== %s\n' "$*"
}
trap 'printf "\n== failed: %s (after %ds; %ds in all)\n" "$step_name" $((SECONDS - step_start)) "$SECONDS"' ERR

step "installing the Rust target thumbv7m-none-eabi"
rustup target add thumbv7m-none-eabi
rustup component add clippy >/dev/null 2>&1 || true
rustup component add rustfmt >/dev/null 2>&1 || true

if cargo fmt --version >/dev/null 2>&1; then
    step "formatting (rustfmt.toml)"
    cargo fmt --all -- --check
    (cd firmware-sim && cargo fmt -- --check)
fi

step "installing qemu-system-arm (the firmware simulation)"
if ! command -v qemu-system-arm >/dev/null 2>&1; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    $sudo apt-get update
    $sudo apt-get install -y qemu-system-arm
fi
qemu-system-arm --version | head -n 1

step "installing man (renders the generated manual pages)"
if ! command -v man >/dev/null 2>&1; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    $sudo apt-get update
    $sudo apt-get install -y man-db
fi

step "installing defmt-print (decodes the firmware's defmt log on the host)"
if ! command -v defmt-print >/dev/null 2>&1; then
    cargo install defmt-print --version =1.2.0 --locked
fi

step "installing the Khronos glTF validator (checks the GLB writer; node and npm)"
if ! command -v npm >/dev/null 2>&1; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    $sudo apt-get update
    $sudo apt-get install -y nodejs npm
fi
(cd scripts/node && npm ci --no-audit --no-fund)

step "core builds for Cortex-M3 (no_std, no allocator)"
cargo build -p zetafill --target thumbv7m-none-eabi --release

if cargo clippy --version >/dev/null 2>&1; then
    step "core lints: no unwrap/expect/panic/indexing that can panic, on the firmware target"
    cargo clippy -p zetafill --target thumbv7m-none-eabi --release -- -D warnings
    step "workspace lints (libraries, binaries, tests, benches, examples)"
    cargo clippy --workspace --release --all-targets -- -D warnings
fi

step "API documentation builds without a broken link"
RUSTDOCFLAGS="-D warnings" cargo doc -p zetafill -p zetafill-display -p zetafill-cli --lib --no-deps

# Three images, each within the flash budget (the link fails beyond it): the 2D scenes on f64
# and on fixed point (one image holding both scalars' copy of the engine overflows the budget),
# and the 3D scenes (2D and 3D together overflow the chip's flash).
for image in zetafill-firmware-f64 zetafill-firmware-fixed zetafill-firmware-space; do
    step "firmware: $image under qemu-system-arm (lm3s6965evb, Cortex-M3, no FPU)"
    (cd firmware-sim && env -u CARGO_TARGET_DIR cargo run --release --bin "$image")
done
if cargo clippy --version >/dev/null 2>&1; then
    (cd firmware-sim && env -u CARGO_TARGET_DIR cargo clippy --release --lib --bins -- -D warnings)
fi

step "the browser page: Chromium (apt), the wasm32 target and wasm-bindgen-cli (web/build.sh), playwright-core (npm)"
if ! command -v chromium >/dev/null 2>&1; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    $sudo apt-get update
    $sudo apt-get install -y chromium
fi
# Warnings denied in the WebAssembly build (the workspace lints above cover the same code on
# the host; a separate clippy run for wasm32 would add two minutes).
RUSTFLAGS="-D warnings" bash web/build.sh
cargo build --release -p zetafill-cli
(cd web && npm ci --no-audit --no-fund && npm test)

step "host tests (release)"
log=$(mktemp)
status=0
cargo test --workspace --release 2>&1 | tee "$log" || status=$?
end_step
awk '/^test result:/ { p += $4; f += $6; i += $8 }
     END { printf "\n== host tests: %d passed, %d failed, %d ignored\n", p, f, i }' "$log"
rm -f "$log"
printf '== every step: %dm%02ds\n' $((SECONDS / 60)) $((SECONDS % 60))
exit "$status"
