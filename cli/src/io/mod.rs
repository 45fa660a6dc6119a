//! The file system: atomic writes of outputs, reading the inputs (SVG outlines, pictures,
//! fonts, with a size limit for every input file), and the rule that no output replaces an
//! input ([`inputs`]).

pub mod font;
pub mod image;
pub mod inputs;
pub mod read;
pub mod svgin;
pub mod write;
