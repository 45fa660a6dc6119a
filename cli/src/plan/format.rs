//! `-o` / `--format`: the format each command writes, given by `--format` or told by the
//! output path's extension, as plain values the commands match on. A path whose extension
//! says nothing is refused naming `--output`.

use crate::args::format::FormatArg;
use crate::args::space::SpaceFormatArg;
use crate::args::stats::ChartFormatArg;
use crate::args::territory::TerritoryFormatArg;
use crate::args::tile::TileFormatArg;
use crate::error::CliError;
use std::path::Path;

/// What `fill` and `line` write.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
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
    /// G-code for a pen plotter or laser.
    Gcode,
}

/// What `tile` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TileFormat {
    /// SVG drawing in mm.
    Svg,
    /// PNG preview (the SVG rendered), or a height map.
    Png,
    /// JSON document (version 1, mode "tile"): the tile's discs.
    Json,
    /// G-code for a plotter or laser (the drawing's outlines).
    Gcode,
}

impl TileFormat {
    /// The format's name.
    pub fn name(self) -> &'static str {
        match self {
            TileFormat::Svg => "svg",
            TileFormat::Png => "png",
            TileFormat::Json => "json",
            TileFormat::Gcode => "gcode",
        }
    }
}

/// What `territory` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TerritoryFormat {
    /// SVG drawing in mm.
    Svg,
    /// PNG preview (the SVG rendered).
    Png,
    /// JSON document (version 1, mode "territory").
    Json,
    /// G-code for a plotter or laser.
    Gcode,
}

impl TerritoryFormat {
    /// The format's name.
    pub fn name(self) -> &'static str {
        match self {
            TerritoryFormat::Svg => "svg",
            TerritoryFormat::Png => "png",
            TerritoryFormat::Json => "json",
            TerritoryFormat::Gcode => "gcode",
        }
    }
}

/// What `space` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpaceFormat {
    /// JSON document (version 1, mode "space").
    Json,
    /// One row per solid.
    Csv,
    /// Binary STL.
    Stl,
    /// Wavefront OBJ.
    Obj,
    /// glTF 2.0 binary.
    Glb,
    /// A shaded render.
    Png,
    /// The sheets of `--slices`.
    Svg,
    /// The digest line.
    Digest,
}

impl From<SpaceFormatArg> for SpaceFormat {
    fn from(f: SpaceFormatArg) -> SpaceFormat {
        match f {
            SpaceFormatArg::Json => SpaceFormat::Json,
            SpaceFormatArg::Csv => SpaceFormat::Csv,
            SpaceFormatArg::Stl => SpaceFormat::Stl,
            SpaceFormatArg::Obj => SpaceFormat::Obj,
            SpaceFormatArg::Glb => SpaceFormat::Glb,
            SpaceFormatArg::Png => SpaceFormat::Png,
            SpaceFormatArg::Svg => SpaceFormat::Svg,
            SpaceFormatArg::Digest => SpaceFormat::Digest,
        }
    }
}

impl SpaceFormat {
    /// The format: `--format`, or else the extension of `path` (JSON for `-`).
    pub fn resolve(given: Option<SpaceFormatArg>, path: &Path) -> Result<SpaceFormat, CliError> {
        use SpaceFormat::*;
        let known = [
            ("json", Json),
            ("csv", Csv),
            ("stl", Stl),
            ("obj", Obj),
            ("glb", Glb),
            ("png", Png),
            ("svg", Svg),
        ];
        format_for(given.map(SpaceFormat::from), path, Json, &known)
    }

    /// The name `--format` takes.
    pub fn name(self) -> &'static str {
        match self {
            SpaceFormat::Json => "json",
            SpaceFormat::Csv => "csv",
            SpaceFormat::Stl => "stl",
            SpaceFormat::Obj => "obj",
            SpaceFormat::Glb => "glb",
            SpaceFormat::Png => "png",
            SpaceFormat::Svg => "svg",
            SpaceFormat::Digest => "digest",
        }
    }
}

/// What `stats trials` and `stats halting` write.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChartFormat {
    /// The numbers, one row per point.
    Csv,
    /// A chart.
    Svg,
}

impl From<FormatArg> for Format {
    fn from(f: FormatArg) -> Format {
        match f {
            FormatArg::Svg => Format::Svg,
            FormatArg::Json => Format::Json,
            FormatArg::Csv => Format::Csv,
            FormatArg::Png => Format::Png,
            FormatArg::Digest => Format::Digest,
            FormatArg::Gcode => Format::Gcode,
        }
    }
}

impl From<TileFormatArg> for TileFormat {
    fn from(f: TileFormatArg) -> TileFormat {
        match f {
            TileFormatArg::Svg => TileFormat::Svg,
            TileFormatArg::Png => TileFormat::Png,
            TileFormatArg::Json => TileFormat::Json,
            TileFormatArg::Gcode => TileFormat::Gcode,
        }
    }
}

impl From<TerritoryFormatArg> for TerritoryFormat {
    fn from(f: TerritoryFormatArg) -> TerritoryFormat {
        match f {
            TerritoryFormatArg::Svg => TerritoryFormat::Svg,
            TerritoryFormatArg::Png => TerritoryFormat::Png,
            TerritoryFormatArg::Json => TerritoryFormat::Json,
            TerritoryFormatArg::Gcode => TerritoryFormat::Gcode,
        }
    }
}

impl From<ChartFormatArg> for ChartFormat {
    fn from(f: ChartFormatArg) -> ChartFormat {
        match f {
            ChartFormatArg::Csv => ChartFormat::Csv,
            ChartFormatArg::Svg => ChartFormat::Svg,
        }
    }
}

impl Format {
    /// The name `--format` takes.
    pub fn name(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Json => "json",
            Format::Csv => "csv",
            Format::Png => "png",
            Format::Digest => "digest",
            Format::Gcode => "gcode",
        }
    }

    /// The format for an output path: `--format` if given, else the extension (`-` needs
    /// `--format` or gets SVG).
    pub fn resolve(given: Option<FormatArg>, path: &Path) -> Result<Format, CliError> {
        if let Some(f) = given {
            return Ok(f.into());
        }
        if path.as_os_str() == "-" {
            return Ok(Format::Svg);
        }
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("svg") => Ok(Format::Svg),
            Some("json") => Ok(Format::Json),
            Some("csv") => Ok(Format::Csv),
            Some("png") => Ok(Format::Png),
            Some("gcode") | Some("nc") => Ok(Format::Gcode),
            _ => Err(CliError::arg(
                "--output",
                format!(
                    "cannot tell the format of '{}'; end it in .svg, .png, .json, .csv, .gcode or .nc, or give --format",
                    path.display()
                ),
            )),
        }
    }
}

impl TileFormat {
    /// The format: `--format`, or else the extension of `path` (SVG for `-`).
    pub fn resolve(given: Option<TileFormatArg>, path: &Path) -> Result<TileFormat, CliError> {
        use TileFormat::*;
        let known = [("svg", Svg), ("png", Png), ("json", Json), ("gcode", Gcode), ("nc", Gcode)];
        format_for(given.map(TileFormat::from), path, Svg, &known)
    }
}

impl TerritoryFormat {
    /// The format: `--format`, or else the extension of `path` (SVG for `-`).
    pub fn resolve(given: Option<TerritoryFormatArg>, path: &Path) -> Result<TerritoryFormat, CliError> {
        use TerritoryFormat::*;
        let known = [("svg", Svg), ("png", Png), ("json", Json), ("gcode", Gcode), ("nc", Gcode)];
        format_for(given.map(TerritoryFormat::from), path, Svg, &known)
    }
}

/// The output format: `given` if any, `stdout` for `-`, otherwise the one `known` pairs with
/// the path's extension (case-insensitive); exit 2 naming `--output` with the extensions to
/// use when none does.
pub fn format_for<F: Copy>(given: Option<F>, path: &Path, stdout: F, known: &[(&str, F)]) -> Result<F, CliError> {
    if let Some(f) = given {
        return Ok(f);
    }
    if path.as_os_str() == "-" {
        return Ok(stdout);
    }
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    if let Some(&(_, f)) = known.iter().find(|(e, _)| ext.as_deref() == Some(*e)) {
        return Ok(f);
    }
    let names: Vec<String> = known.iter().map(|(e, _)| format!(".{e}")).collect();
    let list = match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => names.join(""),
    };
    Err(CliError::arg(
        "--output",
        format!("cannot tell the format of '{}'; end it in {list}, or give --format", path.display()),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_from_extension() {
        assert_eq!(Format::resolve(None, Path::new("a.SVG")).ok(), Some(Format::Svg));
        assert_eq!(Format::resolve(None, Path::new("a.json")).ok(), Some(Format::Json));
        assert!(Format::resolve(None, Path::new("a.txt")).is_err());
        assert_eq!(Format::resolve(None, Path::new("a.gcode")).ok(), Some(Format::Gcode));
        assert_eq!(Format::resolve(None, Path::new("a.NC")).ok(), Some(Format::Gcode));
        assert_eq!(Format::resolve(Some(FormatArg::Csv), Path::new("a.txt")).ok(), Some(Format::Csv));
        assert_eq!(TileFormat::resolve(None, Path::new("-")).ok(), Some(TileFormat::Svg));
        assert_eq!(
            TerritoryFormat::resolve(None, Path::new("a.txt")).map_err(|e| e.to_string()),
            Err("--output: cannot tell the format of 'a.txt'; end it in .svg, .png, .json, .gcode or .nc, or give --format".to_string())
        );
    }

    #[test]
    fn names_are_the_values_of_the_flag() {
        use clap::ValueEnum;
        for a in FormatArg::value_variants() {
            let flag = a.to_possible_value().map(|v| v.get_name().to_string());
            assert_eq!(Some(Format::from(*a).name().to_string()), flag);
        }
    }
}
