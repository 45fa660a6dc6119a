//! The file system: atomic writes of outputs, and reading the inputs (SVG outlines).

pub mod svgin;
pub mod write;
