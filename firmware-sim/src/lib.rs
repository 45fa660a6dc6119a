//! What the firmware images share: the board (clock, stack painting, memory figures), the 2D
//! scenes' runner ([`plane`]) and the report every scene and every image ends with.
//!
//! Three images, each within the same budgets: [`RAM_LIMIT`] of static RAM and stack, and the
//! flash budget of `memory.x` (224 KiB, checked when linking and again by [`finish`]):
//! `zetafill-firmware-f64` and `zetafill-firmware-fixed` run the 2D scenes on f64 and on fixed
//! point (`src/bin/`, both through [`plane::run_image`]), `zetafill-firmware-space` the 3D
//! scenes. The core's 2D and 3D engines together do not fit the chip's 256 KiB of flash, and
//! the 2D engine compiled for both scalars leaves no room in the budget. There is no logic
//! here beyond wiring the core to the board.

#![no_std]
#![deny(unsafe_code)]

pub mod board;
pub mod plane;

use semihosting::{eprintln, process};
use zetafill_display::Outcome;

use board::Board;

/// The target for static RAM plus stack (bytes): reported, see the README.
pub const RAM_TARGET: usize = 48 * 1024;
/// Static RAM plus stack beyond this fails the run.
pub const RAM_LIMIT: usize = RAM_TARGET;

/// Instructions per SysTick tick, as measured.
pub struct Calibration {
    /// Instructions in the calibration loop.
    pub instructions: u64,
    /// SysTick ticks they took.
    pub ticks: u64,
}

impl Calibration {
    /// Measures the clock, prints the `clock` line, and fails when SysTick does not count.
    pub fn measure(board: &Board) -> Calibration {
        let cal = Calibration {
            instructions: board::CALIBRATION_INSTRUCTIONS,
            ticks: board.calibrate(),
        };
        eprintln!("clock instructions={} ticks={}", cal.instructions, cal.ticks);
        defmt::info!("clock: {=u64} instructions in {=u64} SysTick ticks", cal.instructions, cal.ticks);
        if cal.ticks == 0 {
            fail("SysTick does not count: run QEMU with -icount shift=0");
        }
        cal
    }

    /// Instructions in `ticks`.
    pub fn instructions(&self, ticks: u64) -> u64 {
        (u128::from(ticks) * u128::from(self.instructions) / u128::from(self.ticks.max(1))) as u64
    }
}

/// Prints `error MSG` and exits 1.
pub fn fail(msg: &str) -> ! {
    eprintln!("error {}", msg);
    process::exit(1)
}

/// Prints a scene's `digest` and `cost` lines and logs it through defmt; `unit` names what it
/// places ("shapes", "solids").
pub fn report(name: &str, scalar: &str, unit: &str, outcome: &Outcome, cal: &Calibration) {
    let instructions = cal.instructions(outcome.ticks);
    eprintln!("digest {} {} {:016x}", name, outcome.count, outcome.digest);
    eprintln!(
        "cost {} scalar={} placements={} trials={} instructions={}",
        name, scalar, outcome.placed, outcome.trials, instructions
    );
    defmt::info!(
        "{=str} ({=str}): {=u64} {=str}, {=u64} trials, {=u64} instructions per placement",
        name,
        scalar,
        outcome.placed,
        unit,
        outcome.trials,
        instructions / outcome.placed.max(1)
    );
}

/// Prints the scene's `stack` line (the stack painted before it) and returns its depth.
pub fn stack_line(board: &Board, name: &str) -> usize {
    let m = board.memory();
    eprintln!(
        "stack {} static={} stack={} total={}",
        name,
        m.static_ram,
        m.stack,
        m.static_ram + m.stack
    );
    m.stack
}

/// Prints the `memory` line for the deepest scene's stack, checks the budgets, prints `done`
/// and exits 0 (1 after an `error` line naming the budget exceeded).
pub fn finish(board: &Board, deepest: usize) -> ! {
    let m = board.memory();
    let total = m.static_ram + deepest;
    eprintln!(
        "memory static={} stack={} total={} flash={} budget={} target={}",
        m.static_ram, deepest, total, m.flash, m.flash_budget, RAM_TARGET
    );
    defmt::info!(
        "memory: static {=usize} B + stack {=usize} B = {=usize} B, flash {=usize} B of {=usize} B",
        m.static_ram,
        deepest,
        total,
        m.flash,
        m.flash_budget
    );
    if total > RAM_LIMIT {
        eprintln!("error static RAM and stack {} B over the {} B limit", total, RAM_LIMIT);
        process::exit(1);
    }
    if m.flash > m.flash_budget {
        eprintln!("error flash {} B over the {} B budget", m.flash, m.flash_budget);
        process::exit(1);
    }
    eprintln!("done");
    process::exit(0)
}
