//! The file system: atomic writes of outputs, and reading the inputs (SVG outlines, pictures,
//! fonts, with a size limit for every input file).

pub mod font;
pub mod image;
pub mod read;
pub mod svgin;
pub mod write;
