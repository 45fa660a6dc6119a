//! `--region mask:FILE` and `--region text:STRING` resolved when the fill is planned: the
//! picture read and traced, or the font read and the text laid out, so that a bad file, a
//! picture with nothing dark or a character the font lacks stops the command before any work.
//! The region becomes rings (as `polygon:` gives them), and its source the flags that make it
//! again. The flags only these regions read are refused with any other region.
//!
//! A mask's picture (pixel units, y down) becomes the region with its width `--region-width`
//! mm, square pixels, y up, the picture's lower left corner at the origin.

use crate::args::fill::RegionInputArgs;
use crate::error::CliError;
use crate::geometry::{simplify, trace};
use crate::io::font::{FontError, Setting};
use crate::io::svgin::{MAX_COORDINATE_MM, MAX_RINGS, MAX_VERTICES};
use crate::model::region::{polygon_region, RegionSource, RegionSpec};
use crate::output::machine::printable;
use std::path::Path;
use zetafill::Point;

/// `--region-width` when not given (mm): the default region's width.
pub const DEFAULT_REGION_WIDTH: f64 = 200.0;

/// `--text-size` when not given (mm): an em of 50 mm sets capitals about 36 mm tall and a
/// short word about as wide as the default 200 mm region.
pub const DEFAULT_TEXT_SIZE: f64 = 50.0;

/// The smallest `--region-width` and `--text-size`, in mm. Far smaller sizes round the
/// outline's vertices onto each other, or leave the shapes below what the engine resolves;
/// this one still fills as the same outline at 200 mm does.
pub const MIN_INPUT_SIZE: f64 = 1e-6;

/// Refuses a size below [`MIN_INPUT_SIZE`], naming `flag` and the smallest that works.
fn at_least(flag: &str, v: Option<f64>) -> Result<(), CliError> {
    match v {
        Some(v) if v < MIN_INPUT_SIZE => Err(CliError::arg(
            flag,
            format!(
                "{} mm is too small for an outline; give at least {MIN_INPUT_SIZE} mm",
                crate::error::num(v)
            ),
        )),
        _ => Ok(()),
    }
}

/// How far a simplified ring may stray from the traced one, in pixels.
pub const MASK_TOLERANCE: f64 = 0.5;

/// Most vertices a mask may trace to before simplification (64 MiB of vertices).
pub const MAX_TRACED_VERTICES: usize = 4_000_000;

/// The region `spec` resolved: a mask or a text as its rings and their source; any other
/// region as it is, once the flags it does not read are refused.
pub fn resolve(spec: &RegionSpec, a: &RegionInputArgs, glyphs: bool) -> Result<(RegionSpec, Option<RegionSource>), CliError> {
    match spec {
        RegionSpec::Mask { path, threshold } => {
            text_flags(a, glyphs)?;
            mask(path, *threshold, a, spec)
        }
        RegionSpec::Text { lines } => {
            mask_flags(a)?;
            text(lines, a, spec)
        }
        other => {
            mask_flags(a)?;
            text_flags(a, glyphs)?;
            Ok((other.clone(), None))
        }
    }
}

/// Refuses `flag`, given with a region other than `region`.
fn only_for(given: bool, flag: &str, region: &str) -> Result<(), CliError> {
    if given {
        return Err(CliError::arg(
            flag,
            format!("only a --region {region} reads it; drop it, or use a {region} region"),
        ));
    }
    Ok(())
}

/// Refuses the flags of a mask.
fn mask_flags(a: &RegionInputArgs) -> Result<(), CliError> {
    only_for(a.region_width.is_some(), "--region-width", "mask:FILE")?;
    only_for(a.region_sha256.is_some(), "--region-sha256", "mask:FILE")
}

/// Refuses the flags of a text (but the font, with `glyphs`: `--shape glyph:TEXT` reads it).
fn text_flags(a: &RegionInputArgs, glyphs: bool) -> Result<(), CliError> {
    if !glyphs {
        only_for(a.font.is_some(), "--font", "text:STRING (or a --shape glyph:TEXT)")?;
        only_for(a.font_sha256.is_some(), "--font-sha256", "text:STRING (or a --shape glyph:TEXT)")?;
    }
    only_for(a.text_size.is_some(), "--text-size", "text:STRING")?;
    only_for(a.letter_spacing.is_some(), "--letter-spacing", "text:STRING")
}

/// Refuses an input whose SHA-256 is not the one `flag` gave (`what` names the input).
pub fn check_digest(flag: &str, path: &Path, actual: &str, want: Option<&String>, what: &str) -> Result<(), CliError> {
    match want {
        Some(want) if !want.eq_ignore_ascii_case(actual) => Err(CliError::arg(
            flag,
            printable(&format!(
                "{} has SHA-256 {actual}, not {want}: the {what} changed since the file was made; drop {flag} to fill with it as it is",
                path.display()
            )),
        )),
        _ => Ok(()),
    }
}

/// A picture's dark areas as rings in mm.
fn mask(path: &Path, threshold: f64, a: &RegionInputArgs, spec: &RegionSpec) -> Result<(RegionSpec, Option<RegionSource>), CliError> {
    at_least("--region-width", a.region_width)?;
    let grey = crate::io::image::read_grey(path).map_err(|e| CliError::arg("--region", printable(&e)))?;
    check_digest("--region-sha256", path, &grey.sha256, a.region_sha256.as_ref(), "picture")?;
    let width = a.region_width.unwrap_or(DEFAULT_REGION_WIDTH);
    let traced = trace::trace(&grey.luma, grey.width, grey.height, threshold as f32, MAX_TRACED_VERTICES).map_err(|e| {
        CliError::arg(
            "--region",
            printable(&format!(
                "'{}' traces to more than {} vertices; use a smaller or smoother picture",
                path.display(),
                e.vertices
            )),
        )
    })?;
    if traced.ends.is_empty() {
        return Err(CliError::arg(
            "--region",
            printable(&format!(
                "'{}' has no dark area at threshold {threshold} (areas under {} square pixels are dropped as specks); raise the threshold (mask:FILE:0.8) or darken the picture",
                path.display(),
                trace::MIN_RING_AREA
            )),
        ));
    }
    let rings = simplify::simplify(&traced, MASK_TOLERANCE);
    let too_many = |what: String| {
        CliError::arg(
            "--region",
            printable(&format!("'{}' traces to {what}; use a smaller or smoother picture", path.display())),
        )
    };
    if rings.points.len() > MAX_VERTICES {
        return Err(too_many(format!(
            "{} vertices, more than the {MAX_VERTICES} an outline may have",
            rings.points.len()
        )));
    }
    if rings.ends.len() > MAX_RINGS {
        return Err(too_many(format!(
            "{} rings, more than the {MAX_RINGS} an outline may have",
            rings.ends.len()
        )));
    }
    let points = to_region(&rings.points, grey.width, grey.height, width);
    within_reach(&points, "--region-width", "a smaller --region-width")?;
    let source = RegionSource {
        region: spec.input_name().unwrap_or_default(),
        region_width: Some(width),
        region_sha256: Some(grey.sha256.clone()),
        text_size: None,
        letter_spacing: None,
        font: None,
        font_sha256: None,
    };
    Ok((RegionSpec::Polygon { points, ends: rings.ends }, Some(source)))
}

/// Pixel coordinates (y down) as mm in the region's frame: the picture `width_px x height_px`
/// `width` mm wide, y up, its lower left corner at the origin.
pub fn to_region(points: &[Point<f64>], width_px: usize, height_px: usize, width: f64) -> Vec<Point<f64>> {
    let s = width / width_px as f64;
    let h = height_px as f64;
    points.iter().map(|p| Point::new(p.x * s, (h - p.y) * s)).collect()
}

/// Refuses a region reaching farther from the origin than any region may (as an SVG outline),
/// naming `flag` and suggesting `fix`.
fn within_reach(points: &[Point<f64>], flag: &str, fix: &str) -> Result<(), CliError> {
    let far = points.iter().map(|p| p.x.abs().max(p.y.abs())).fold(0.0, f64::max);
    if far > MAX_COORDINATE_MM {
        return Err(CliError::arg(
            flag,
            format!(
                "the region would reach {} mm from the origin, beyond {} mm; use {fix}",
                crate::error::num(far),
                crate::error::num(MAX_COORDINATE_MM)
            ),
        ));
    }
    Ok(())
}

/// A text's letters as rings in mm.
fn text(lines: &[String], a: &RegionInputArgs, spec: &RegionSpec) -> Result<(RegionSpec, Option<RegionSource>), CliError> {
    at_least("--text-size", a.text_size)?;
    let file = match &a.font {
        Some(path) => {
            let f = crate::io::font::read_font(path).map_err(|e| font_error(e, Some(path)))?;
            check_digest("--font-sha256", path, &f.sha256, a.font_sha256.as_ref(), "font")?;
            Some(f)
        }
        None if a.font_sha256.is_some() => {
            return Err(CliError::arg(
                "--font-sha256",
                "names the --font file, and none is given: drop it, or give --font FILE",
            ))
        }
        None => None,
    };
    let bytes = match &file {
        Some(f) => f.bytes.as_slice(),
        None => crate::io::font::builtin().ok_or_else(|| font_error(FontError::NoBuiltin, None))?,
    };
    let set = Setting {
        size: a.text_size.unwrap_or(DEFAULT_TEXT_SIZE),
        spacing: a.letter_spacing.unwrap_or(0.0),
        max_vertices: MAX_VERTICES,
        max_rings: MAX_RINGS,
    };
    let letters = crate::io::font::lay_out(bytes, lines, set).map_err(|e| font_error(e, a.font.as_deref()))?;
    within_reach(
        &letters.points,
        "--text-size",
        "a smaller --text-size or --letter-spacing, or a shorter text",
    )?;
    let mut scratch = Vec::new();
    if let Err(e) = polygon_region(&letters.points, &letters.ends, &mut scratch) {
        return Err(letters_error(&letters, e, a.font.is_some()));
    }
    let source = RegionSource {
        region: spec.input_name().unwrap_or_default(),
        region_width: None,
        region_sha256: None,
        text_size: Some(set.size),
        letter_spacing: a.letter_spacing.filter(|s| *s != 0.0),
        font: a.font.as_ref().map(|p| p.display().to_string()),
        font_sha256: file.map(|f| f.sha256),
    };
    Ok((
        RegionSpec::Polygon {
            points: letters.points,
            ends: letters.ends,
        },
        Some(source),
    ))
}

/// Why laid-out letters make no region: a glyph whose own outline the core refuses, or
/// letters that touch or overlap each other.
fn letters_error(letters: &crate::io::font::Letters, e: zetafill::RegionError, own_font: bool) -> CliError {
    let mut scratch = Vec::new();
    let mut first = 0usize;
    for &(ch, last) in &letters.glyphs {
        let start = first.checked_sub(1).and_then(|i| letters.ends.get(i)).copied().unwrap_or(0);
        let ends: Vec<usize> = letters.ends.get(first..last).unwrap_or(&[]).iter().map(|&x| x - start).collect();
        let stop = letters.ends.get(last.wrapping_sub(1)).copied().unwrap_or(start);
        let points = letters.points.get(start..stop).unwrap_or(&[]);
        if let Err(glyph) = polygon_region(points, &ends, &mut scratch) {
            let flag = if own_font { "--font" } else { "--region" };
            return CliError::arg(
                flag,
                printable(&format!(
                    "the font's outline of '{}' is not a simple outline ({glyph}); leave the letter out or use another --font",
                    ch.escape_debug()
                )),
            );
        }
        first = last;
    }
    CliError::arg(
        "--region",
        format!("the letters touch or overlap once laid out ({e}); add --letter-spacing 1 (mm) or more to set them apart"),
    )
}

/// A font or text that gives no outline, worded for the flag to change.
pub fn font_error(e: FontError, path: Option<&Path>) -> CliError {
    let name = path.map_or_else(|| "the built-in font".to_string(), |p| format!("'{}'", p.display()));
    let (flag, msg) = match e {
        FontError::Read(e) => ("--font", format!("cannot read {name}: {e}")),
        FontError::Empty => ("--font", format!("{name} is empty; give a TrueType or OpenType font file")),
        FontError::NoBuiltin => ("--font", format!("{name} is not loaded in this build; give --font FILE")),
        FontError::NotAFont(why) => (
            "--font",
            format!("{name} is not a TrueType or OpenType font ({why}); give a .ttf or .otf file"),
        ),
        FontError::Missing(c) => (
            if path.is_some() { "--font" } else { "--region" },
            format!(
                "{name} has no glyph for '{}' (U+{:04X}); leave it out of the text or give a --font that has it",
                c.escape_debug(),
                u32::from(c)
            ),
        ),
        FontError::NoOutline => (
            "--region",
            "the text has no letter with an outline (only spaces); give at least one visible character".to_string(),
        ),
        FontError::TooManyVertices(n) => (
            "--region",
            format!("the text's letters need more than {n} vertices; use a shorter text or a simpler --font"),
        ),
        FontError::TooManyRings(n) => (
            "--region",
            format!("the text's letters have more than {n} rings; use a shorter text"),
        ),
    };
    CliError::arg(flag, printable(&msg))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::font::Letters;

    /// A ring as (x, y) pairs.
    type Ring<'a> = &'a [(f64, f64)];

    /// Letters from (character, its rings).
    fn letters(glyphs: &[(char, &[Ring<'_>])]) -> Letters {
        let mut l = Letters::default();
        for (ch, rings) in glyphs {
            for r in *rings {
                l.points.extend(r.iter().map(|&(x, y)| Point::new(x, y)));
                l.ends.push(l.points.len());
            }
            l.glyphs.push((*ch, l.ends.len()));
        }
        l
    }

    #[test]
    fn touching_letters_and_broken_glyphs_are_told_apart() {
        let square: &[(f64, f64)] = &[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
        let moved: &[(f64, f64)] = &[(8.0, 0.0), (18.0, 0.0), (18.0, 10.0), (8.0, 10.0)];
        let bow: &[(f64, f64)] = &[(30.0, 0.0), (40.0, 10.0), (40.0, 0.0), (30.0, 10.0)];
        let e = zetafill::RegionError::SelfIntersecting;
        let overlap = letters_error(&letters(&[('a', &[square]), ('b', &[moved])]), e, false).to_string();
        assert!(overlap.contains("--region") && overlap.contains("--letter-spacing"), "{overlap}");
        let broken = letters_error(&letters(&[('a', &[square]), ('x', &[bow])]), e, true).to_string();
        assert!(broken.starts_with("--font") && broken.contains("'x'"), "{broken}");
        let builtin = letters_error(&letters(&[('x', &[bow]), ('a', &[moved])]), e, false).to_string();
        assert!(builtin.starts_with("--region") && builtin.contains("'x'"), "{builtin}");
    }

    #[test]
    fn pixels_become_mm_with_y_up() {
        let p = to_region(&[Point::new(0.0, 0.0), Point::new(40.0, 10.0)], 40, 20, 200.0);
        assert_eq!(p, [Point::new(0.0, 100.0), Point::new(200.0, 50.0)]);
    }
}
