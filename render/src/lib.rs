//! zetafill's drawings and writers: the documents each command writes ([`model`]), one drawing
//! model of layers, paths and pens, the shared plane geometry ([`geometry`]: Voronoi cells,
//! clipping, mask tracing), one writer per output format ([`output`]: SVG, G-code, PNG, height
//! maps, JSON, CSV, digests, STL, OBJ, GLB, renders) and the error values ([`error`]).
//!
//! No argument parsing and no file system: a writer takes plain options and returns bytes, so
//! the command-line tool and the browser page call the same code and write the same files.
//! Which module may use which is in docs/architecture.md.

#![deny(missing_docs)]

pub mod error;
pub mod geometry;
pub mod model;
pub mod output;
