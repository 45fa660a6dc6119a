//! The 2D scenes on the board: what the images `zetafill-firmware-f64` and
//! `zetafill-firmware-fixed` run, each on one scalar.
//!
//! [`run_image`] runs every scene of `zetafill_display::SCENES` on the image's scalar in a
//! 1,024-shape engine that lives on the stack (a cell-sampler scene in a smaller frame with its
//! cells), drawing each shape onto the 128x64 monochrome framebuffer as it is placed, and
//! reports through semihosting:
//!
//! - on the host's stderr, plain text lines that the host test parses:
//!   `clock instructions=I ticks=T`, `digest NAME COUNT HEX16`, `cost NAME scalar=S placements=P trials=T instructions=I`,
//!   `frame NAME FILE`, `stack NAME static=B stack=B total=B` (the stack painted anew before
//!   each scene), `memory static=B stack=B total=B flash=B budget=B target=B`, then `done`;
//! - each frame as a binary PBM file `frame-NAME.pbm` in QEMU's working directory;
//! - on the host's stdout, defmt log frames (decoded by `defmt-print -e ELF`).
//!
//! Exit status 0 when every scene ran and the memory stays within the budgets; 1 on any error
//! (invalid parameters, capacity, halting, a failed file write, over budget), after a line
//! `error ...`. A panic (there should be none) prints its message and exits non-zero too.
//!
//! The f64 and the fixed-point scenes are two images because every generic part of the core
//! (engine, samplers, clearance tests, drawing) is compiled once per scalar: the two copies
//! together leave too little of the flash budget. Each image holds one copy.

use core::ffi::CStr;
use heapless::String;
use semihosting::io::Write as _;
use semihosting::{eprintln, process};
use zetafill::{Fixed, Placed, Scalar, Storage};
use zetafill_display::draw::{Frame, PBM_HEADER};
use zetafill_display::scenes::{
    run, run_fast, Outcome, RunError, ScalarKind, Scene, CAPACITY, FAST_CAPACITY, FAST_CELLS, FAST_INDEX_WORDS, INDEX_WORDS, SCENES,
};

use crate::board::Board;
use crate::{fail, finish, report, stack_line, Calibration};

/// A scalar a 2D image runs its scenes on: the scenes whose [`Scene::scalar`] is [`Self::KIND`].
pub trait PlaneScalar: Scalar + Default {
    /// The scenes' scalar.
    const KIND: ScalarKind;
}

impl PlaneScalar for f64 {
    const KIND: ScalarKind = ScalarKind::F64;
}

impl PlaneScalar for Fixed {
    const KIND: ScalarKind = ScalarKind::Fixed;
}

/// The scenes an image on scalar `S` runs, in the order of `SCENES`.
fn scenes<S: PlaneScalar>() -> impl Iterator<Item = &'static Scene> + Clone {
    SCENES.iter().filter(|s| s.scalar == S::KIND)
}

/// The image's `main`: runs every scene on scalar `S`, then checks the budgets and exits
/// (`image` names it in the defmt log).
pub fn run_image<S: PlaneScalar>(image: &str) -> ! {
    let Some(peripherals) = cortex_m::Peripherals::take() else {
        fail("peripherals already taken")
    };
    let board = Board::init(peripherals.SYST);
    defmt::info!(
        "{=str}: {=usize} scenes, engine capacity {=usize} shapes",
        image,
        scenes::<S>().count(),
        CAPACITY
    );
    let cal = Calibration::measure(&board);
    let mut deepest = 0;
    for scene in scenes::<S>() {
        board.repaint();
        let ok = if scene.fast {
            run_scene_fast::<S>(scene, &board, &cal)
        } else {
            run_scene::<S>(scene, &board, &cal)
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
    let outcome = run(scene, storage, &mut frame, || clock.now());
    scene_done(scene, outcome, &frame, cal)
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
    let outcome = run_fast(scene, storage, &mut cells, &mut frame, || clock.now());
    scene_done(scene, outcome, &frame, cal)
}

/// Reports a scene's digest and cost and writes its frame, or says why it failed.
fn scene_done<E>(scene: &Scene, outcome: Result<Outcome, RunError<E>>, frame: &Frame, cal: &Calibration) -> bool
where
    RunError<E>: core::fmt::Display,
{
    match outcome {
        Ok(o) => {
            report(scene.name, scene.scalar.name(), "shapes", &o, cal);
            write_frame(scene.name, frame)
        }
        Err(e) => {
            eprintln!("error {}: {}", scene.name, e);
            log_error(scene.name, &e);
            false
        }
    }
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
