//! zetafill's 2D scenes on 32.32 fixed point on a Cortex-M3 (TI LM3S6965, no FPU) under
//! qemu-system-arm: every scene of `zetafill_display::SCENES` whose scalar is
//! `zetafill::Fixed`, drawn on the display. The f64 scenes are the image
//! `zetafill-firmware-f64`, the 3D ones `zetafill-firmware-space`; the report lines and exit
//! codes are described in the crate's `plane` module.

#![no_std]
#![no_main]
#![deny(unsafe_code)]

use cortex_m_rt::entry;
use defmt_semihosting as _;
use zetafill::Fixed;

#[entry]
fn main() -> ! {
    zetafill_firmware_sim::plane::run_image::<Fixed>("zetafill-firmware-fixed")
}
