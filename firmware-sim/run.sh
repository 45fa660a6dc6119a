#!/usr/bin/env bash
# Cargo's runner for thumbv7m-none-eabi (see .cargo/config.toml): runs the firmware ELF under
# qemu-system-arm (machine lm3s6965evb: Cortex-M3, no FPU) with semihosting and a virtual
# clock of one nanosecond per instruction (-icount shift=0). The firmware's report lines go to
# stderr, its defmt log to stdout, decoded here by defmt-print when it is installed; the
# frames are written as PBM files into $ZETAFILL_FW_OUT (default target/frames), which every
# image shares (scene names are unique).
set -euo pipefail
elf="$(realpath "$1")"
out="${ZETAFILL_FW_OUT:-$(dirname "$(realpath "$0")")/target/frames}"
mkdir -p "$out"
cd "$out"
qemu=(qemu-system-arm -cpu cortex-m3 -machine lm3s6965evb -display none -serial none -monitor none
      -semihosting-config enable=on,target=native -icount shift=0 -kernel "$elf")
if command -v defmt-print >/dev/null 2>&1; then
    "${qemu[@]}" | defmt-print -e "$elf"
else
    log="defmt-$(basename "$elf").bin"
    echo "defmt-print not installed (cargo install defmt-print --version =1.2.0 --locked): defmt log kept in $out/$log" >&2
    "${qemu[@]}" > "$log"
fi
