//! zetafill's 3D fill on a Cortex-M3 (TI LM3S6965, no FPU) under qemu-system-arm: the third
//! firmware image (the 2D and 3D engines together do not fit the chip's 256 KiB of flash).
//!
//! Runs every scene of `zetafill_display::SPACE_SCENES` in a 256-solid `SpaceEngine` that
//! lives on the stack (so the f64 and the fixed-point scenes reuse the same RAM) and reports
//! through semihosting, in the lines of the 2D image: `clock ...`, then per scene
//! `digest NAME COUNT HEX16` (the core's `space_digest`, as `zetafill space ... --format
//! digest` prints it), `cost NAME ...` and `stack NAME ...`, then `noise HEX16` (the digest
//! of `zetafill_display::noise`), `memory ...` and `done`;
//! defmt log frames on stdout. Exit status 0 when every scene ran within the memory budget,
//! 1 after an `error ...` line otherwise. No frames: the 3D scenes draw nothing.

#![no_std]
#![no_main]
#![deny(unsafe_code)]

use cortex_m_rt::entry;
use defmt_semihosting as _;
use semihosting::{eprintln, process};
use zetafill::space::{Placed as PlacedSolid, Storage as SpaceStorage};
use zetafill::{Fixed, Scalar};
use zetafill_display::scenes::ScalarKind;
use zetafill_display::space::{run_space, SpaceRunError, SpaceScene, SPACE_CAPACITY, SPACE_INDEX_WORDS, SPACE_SCENES};
use zetafill_firmware_sim::board::Board;
use zetafill_firmware_sim::{fail, finish, report, stack_line, Calibration};

#[entry]
fn main() -> ! {
    let Some(peripherals) = cortex_m::Peripherals::take() else {
        fail("peripherals already taken")
    };
    let board = Board::init(peripherals.SYST);
    defmt::info!(
        "zetafill firmware-space: {=usize} scenes, engine capacity {=usize} solids",
        SPACE_SCENES.len(),
        SPACE_CAPACITY
    );
    let cal = Calibration::measure(&board);
    let mut deepest = 0;
    for scene in SPACE_SCENES {
        board.repaint();
        let ok = match scene.scalar {
            ScalarKind::F64 => run_scene::<f64>(scene, &board, &cal),
            ScalarKind::Fixed => run_scene::<Fixed>(scene, &board, &cal),
        };
        if !ok {
            process::exit(1);
        }
        deepest = deepest.max(stack_line(&board, scene.name));
    }
    // The noise fields that density maps will use, bit for bit as on the host.
    match zetafill_display::noise::noise_digest() {
        Some(h) => eprintln!("noise {:016x}", h),
        None => fail("noise fields"),
    }
    finish(&board, deepest)
}

/// Runs one 3D scene on scalar `S` with the engine's storage on this frame of the stack.
#[inline(never)]
fn run_scene<S: Scalar + Default>(scene: &SpaceScene, board: &Board, cal: &Calibration) -> bool {
    let mut solids = [PlacedSolid::<S>::default(); SPACE_CAPACITY];
    let mut index = [0u32; SPACE_INDEX_WORDS];
    let storage = SpaceStorage {
        solids: &mut solids,
        index: &mut index,
    };
    let mut clock = board.clock();
    match run_space(scene, storage, || clock.now()) {
        Ok(outcome) => {
            report(scene.name, scene.scalar.name(), "solids", &outcome, cal);
            true
        }
        Err(e) => {
            eprintln!("error {}: {}", scene.name, e);
            match e {
                SpaceRunError::Param(e) => defmt::error!("{=str}: invalid parameters: {}", scene.name, e),
                SpaceRunError::Step(e) => defmt::error!("{=str}: {}", scene.name, e),
            }
            false
        }
    }
}
