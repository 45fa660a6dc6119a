//! `--format`: the output formats each command's flag accepts. The plan turns them, or the
//! output path's extension, into the plain format the command writes
//! ([`crate::plan::format`]).

/// The formats `-o` / `--format` accept for `fill` and `line`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FormatArg {
    /// SVG drawing in mm.
    Svg,
    /// JSON document (version 1).
    Json,
    /// One row per shape.
    Csv,
    /// PNG preview (the SVG rendered).
    Png,
    /// One line `COUNT HEX16`: the determinism digest of every placed shape.
    Digest,
    /// G-code for a pen plotter or laser (`--machine`).
    Gcode,
}
