//! zetafill's 2D scenes on f64 (soft-float) on a Cortex-M3 (TI LM3S6965, no FPU) under
//! qemu-system-arm: every scene of `zetafill_display::SCENES` whose scalar is `f64`, drawn on
//! the display. The fixed-point scenes are the image `zetafill-firmware-fixed`, the 3D ones
//! `zetafill-firmware-space`; the report lines and exit codes are described in the crate's
//! `plane` module.

#![no_std]
#![no_main]
#![deny(unsafe_code)]

use cortex_m_rt::entry;
use defmt_semihosting as _;

#[entry]
fn main() -> ! {
    zetafill_firmware_sim::plane::run_image::<f64>("zetafill-firmware-f64")
}
