//! zetafill on a Cortex-M3 (TI LM3S6965, no FPU) under qemu-system-arm.
//!
//! Runs every scene of `zetafill_display::SCENES` in a 1,024-shape engine that lives on the
//! stack (so the f64 and the fixed-point scenes reuse the same RAM), drawing each shape onto a
//! 128x128 monochrome framebuffer as it is placed, and reports through semihosting:
//!
//! - on the host's stderr, plain text lines that the host test parses:
//!   `clock instructions=I ticks=T`, `digest NAME COUNT HEX16`, `cost NAME scalar=S placements=P trials=T instructions=I`,
//!   `frame NAME FILE`, `stack NAME static=B stack=B total=B` (the stack painted anew before
//!   each scene), `memory static=B stack=B total=B flash=B target=B`, then `done`;
//! - each frame as a binary PBM file `frame-NAME.pbm` in QEMU's working directory;
//! - on the host's stdout, defmt log frames (decoded by `defmt-print -e ELF`).
//!
//! Exit status 0 when every scene ran and the memory stays within the limits; 1 on any error
//! (invalid parameters, capacity, halting, a failed file write, over budget), after a line
//! `error ...`. A panic (there should be none) prints its message and exits non-zero too.
//! There is no logic here beyond wiring the core and the display crate to the board. The 3D
//! scenes are a second image, `zetafill-firmware-space` (see the crate's library).

#![no_std]
#![no_main]
#![deny(unsafe_code)]

use core::ffi::CStr;
use cortex_m_rt::entry;
use defmt_semihosting as _;
use heapless::String;
use semihosting::io::Write as _;
use semihosting::{eprintln, process};
use zetafill::{Fixed, Placed, Scalar, Storage};
use zetafill_display::draw::{Frame, PBM_HEADER};
use zetafill_display::scenes::{
    run, run_fast, RunError, ScalarKind, Scene, CAPACITY, FAST_CAPACITY, FAST_CELLS, FAST_INDEX_WORDS, INDEX_WORDS, SCENES,
};
use zetafill_firmware_sim::board::Board;
use zetafill_firmware_sim::{fail, finish, report, stack_line, Calibration};

#[entry]
fn main() -> ! {
    let Some(peripherals) = cortex_m::Peripherals::take() else {
        fail("peripherals already taken")
    };
    let board = Board::init(peripherals.SYST);
    defmt::info!(
        "zetafill firmware-sim: {=usize} scenes, engine capacity {=usize} shapes",
        SCENES.len(),
        CAPACITY
    );
    let cal = Calibration::measure(&board);
    let mut deepest = 0;
    for scene in SCENES {
        board.repaint();
        let ok = match scene.scalar {
            ScalarKind::F64 if scene.fast => run_scene_fast::<f64>(scene, &board, &cal),
            ScalarKind::Fixed if scene.fast => run_scene_fast::<Fixed>(scene, &board, &cal),
            ScalarKind::F64 => run_scene::<f64>(scene, &board, &cal),
            ScalarKind::Fixed => run_scene::<Fixed>(scene, &board, &cal),
        };
        if !ok {
            process::exit(1);
        }
        deepest = deepest.max(stack_line(&board, scene.name));
    }
    finish(&board, deepest)
}

/// Logs a failed scene through defmt: the core's error values derive `defmt::Format` (its
/// `defmt` feature), so the host decodes them without the firmware formatting any text.
fn log_error<E>(scene: &str, e: &RunError<E>) {
    match e {
        RunError::Region(e) => defmt::error!("{=str}: invalid region: {}", scene, e),
        RunError::Param(e) => defmt::error!("{=str}: invalid parameters: {}", scene, e),
        RunError::Step(e) => defmt::error!("{=str}: {}", scene, e),
        RunError::Draw(_) => defmt::error!("{=str}: the display refused a drawing", scene),
    }
}

/// Runs one scene on scalar `S` with the engine's storage on this frame of the stack.
#[inline(never)]
fn run_scene<S: Scalar + Default>(scene: &Scene, board: &Board, cal: &Calibration) -> bool {
    let mut shapes = [Placed::<S>::default(); CAPACITY];
    let mut index = [0u32; INDEX_WORDS];
    let mut frame = Frame::new();
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let mut clock = board.clock();
    let outcome = match run(scene, storage, &mut frame, || clock.now()) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error {}: {}", scene.name, e);
            log_error(scene.name, &e);
            return false;
        }
    };
    report(scene.name, scene.scalar.name(), "shapes", &outcome, cal);
    write_frame(scene.name, &frame)
}

/// Runs a cell-sampler scene on scalar `S`: fewer shape slots, and the cells, on this frame
/// of the stack (so the other scenes' frames hold no cells).
#[inline(never)]
fn run_scene_fast<S: Scalar + Default>(scene: &Scene, board: &Board, cal: &Calibration) -> bool {
    let mut shapes = [Placed::<S>::default(); FAST_CAPACITY];
    let mut index = [0u32; FAST_INDEX_WORDS];
    let mut cells = [[0u64; 4]; FAST_CELLS];
    let mut frame = Frame::new();
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let mut clock = board.clock();
    let outcome = match run_fast(scene, storage, &mut cells, &mut frame, || clock.now()) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error {}: {}", scene.name, e);
            log_error(scene.name, &e);
            return false;
        }
    };
    report(scene.name, scene.scalar.name(), "shapes", &outcome, cal);
    write_frame(scene.name, &frame)
}

/// Writes `frame-NAME.pbm` through semihosting.
fn write_frame(name: &str, frame: &Frame) -> bool {
    // The file name, then the NUL that semihosting wants; a name too long for it fails.
    let mut path: String<64> = String::new();
    if ["frame-", name, ".pbm", "\0"].iter().any(|part| path.push_str(part).is_err()) {
        return false;
    }
    let Ok(cpath) = CStr::from_bytes_with_nul(path.as_bytes()) else {
        return false;
    };
    let written = semihosting::fs::File::create(cpath).and_then(|mut file| {
        file.write_all(PBM_HEADER)?;
        file.write_all(frame.data())
    });
    if written.is_err() {
        eprintln!("error {}: cannot write the frame file", name);
        return false;
    }
    eprintln!("frame {} {}", name, path.strip_suffix('\0').unwrap_or(&path));
    true
}
