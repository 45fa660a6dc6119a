//! # zetafill-display
//!
//! The generative display shared by the firmware (`firmware-sim/`, a Cortex-M3 under QEMU) and
//! the host tests, so that both draw a fill through the very same code:
//!
//! - [`draw`]: maps a region onto a display and draws each placed shape, exactly the
//!   [`zetafill::Geo`] the engine tested, onto any `embedded-graphics` [`DrawTarget`]: as an
//!   outline on [`BinaryColor`] pixels, or filled in any colour type (the pixels whose
//!   centres lie inside it); [`draw::Frame`] is the 128x64 monochrome framebuffer (an SSD1306
//!   OLED's worth, 1 KiB) whose bytes are the data of a binary PBM image;
//! - [`scenes`]: the scenes the firmware runs (the canonical runs of docs/firmware.md and one
//!   per shape kind, region and scalar), the storage sizes of the 1,024-shape engine, and
//!   [`scenes::run`], which fills a scene step by step, drawing as it goes, and returns the
//!   count, the determinism digest and the trials;
//! - [`space`]: the 3D scenes (solids in a box or a ball, f64 and fixed point) in a
//!   256-solid [`zetafill::space::Engine`], and [`space::run_space`], which returns the same
//!   [`Outcome`] with the 3D digest.
//!
//! `no_std`, no allocator, no panics; drawing uses only integer and IEEE basic `f64`
//! operations, so the pixels are the same on every target.
//!
//! [`DrawTarget`]: embedded_graphics::draw_target::DrawTarget
//! [`BinaryColor`]: embedded_graphics::pixelcolor::BinaryColor

#![no_std]
#![deny(missing_docs, unsafe_code)]
#![deny(clippy::unwrap_used, clippy::expect_used, clippy::panic, clippy::indexing_slicing)]

pub mod draw;
pub mod noise;
pub mod scenes;
pub mod space;

pub use draw::{Frame, View};
pub use scenes::{run, Outcome, RunError, ScalarKind, Scene, SCENES};
pub use space::{run_space, SpaceRunError, SpaceScene, SPACE_SCENES};
