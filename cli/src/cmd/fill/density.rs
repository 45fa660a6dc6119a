//! `--density` as the core sees it: noise through a contrast, or a picture stretched over the
//! region's bounding box, with an upper bound of the density over any box (for the cell
//! sampler, which draws its cells by area times that bound: see [`zetafill::Density`]).
//!
//! A picture's bound comes from a pyramid of its luminance: level `L` holds, for each block of
//! `2^L x 2^L` pixels, the darkest of them (the lightest, inverted: the pixel of the highest
//! density). The blend at a point is a convex combination of the (at most four) pixels around
//! it, so over a box it is no darker than the darkest pixel the box's blends use; the pyramid
//! answers that from at most two by two blocks of the finest level whose blocks hold the box's
//! ends, a superset of those pixels, in constant time.

use crate::error::CliError;
use crate::io::image::Grey;
use crate::model::density::DensitySpec;
use crate::plan::fill::FillRun;
use std::sync::Arc;
use zetafill::Region;

/// The most lattice cells of a noise across the region (the core's limit for a periodic one).
const MAX_NOISE_CELLS: f64 = (1u64 << 40) as f64;

/// A bound leaves this relative margin above the darkest blend, so the rounding of a blend
/// (a few units in the last place) never takes the density above it.
const MARGIN: f64 = 1e-12;

/// A `--density` as the core sees it.
pub(super) enum Field {
    /// Noise: `0.5 + contrast (noise - 0.5)`, clamped (no bound below 1 is known).
    Noise { noise: zetafill::Noise, contrast: f64 },
    /// A density on a wallpaper group's torus, read in the lattice's own coordinates: at
    /// `(x - shear y) mod ax, y`, so that it repeats with the lattice vectors `(ax, 0)` and
    /// `(shear by, by)`, and a picture covers one primitive cell (a parallelogram on an
    /// oblique or hexagonal lattice).
    Lattice { field: Box<Field>, ax: f64, shear: f64 },
    /// A picture over the region's bounding box `(x0, y0, x1, y1)`.
    Picture {
        grey: Arc<Grey>,
        pyramid: Pyramid,
        bbox: (f64, f64, f64, f64),
        invert: bool,
        gamma: f64,
        floor: f64,
    },
}

impl Field {
    /// The density at luminance `l` of a picture.
    fn of_luma(l: f64, invert: bool, gamma: f64, floor: f64) -> f64 {
        let t = (if invert { l } else { 1.0 - l }).clamp(0.0, 1.0);
        // `t^1` is `t` exactly: the common case skips the power.
        floor + (1.0 - floor) * if gamma == 1.0 { t } else { libm::pow(t, gamma) }
    }
}

impl zetafill::Density for Field {
    fn at(&self, x: f64, y: f64) -> f64 {
        match self {
            Field::Lattice { field, ax, shear } => field.at((x - shear * y).rem_euclid(*ax), y),
            Field::Noise { noise, contrast } => (0.5 + contrast * (noise.at(x, y) - 0.5)).clamp(0.0, 1.0),
            Field::Picture {
                grey,
                bbox,
                invert,
                gamma,
                floor,
                ..
            } => Field::of_luma(bilinear(grey, bbox, x, y), *invert, *gamma, *floor),
        }
    }

    fn max_over(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        match self {
            Field::Noise { .. } => 1.0,
            Field::Lattice { field, ax, shear } => {
                // The lattice coordinate over the box: from its corner of least `x - shear y`
                // to that of the most, widened by far more than the rounding of `at`.
                let (lo, hi) = if *shear >= 0.0 {
                    (x0 - shear * y1, x1 - shear * y0)
                } else {
                    (x0 - shear * y0, x1 - shear * y1)
                };
                let slack = 1e-9 * ax;
                let (lo, span) = ((lo - slack).rem_euclid(*ax), hi - lo + 2.0 * slack);
                if span.is_nan() || span >= *ax {
                    field.max_over(0.0, y0, *ax, y1)
                } else if lo + span <= *ax {
                    field.max_over(lo, y0, lo + span, y1)
                } else {
                    field.max_over(lo, y0, *ax, y1).max(field.max_over(0.0, y0, lo + span - ax, y1))
                }
            }
            Field::Picture {
                grey,
                pyramid,
                bbox,
                invert,
                gamma,
                floor,
            } => {
                // Pixel columns and rows whose values the blends over the box use: from the
                // top-left corner's pixel to the one after the bottom-right corner's.
                let (u0, v0) = blend_uv(grey, bbox, x0, y1);
                let (u1, v1) = blend_uv(grey, bbox, x1, y0);
                let l = pyramid.range(u0 as usize, u1 as usize + 1, v0 as usize, v1 as usize + 1);
                Field::of_luma(f64::from(l), *invert, *gamma, *floor) * (1.0 + MARGIN)
            }
        }
    }
}

/// The blend coordinates of `(x, y)`: in pixels, pixel centres at whole numbers, rows running
/// down from the box's top, clamped to the pixels. Monotone in `x` and in `-y`, as every step
/// rounds monotonically.
fn blend_uv(g: &Grey, bbox: &(f64, f64, f64, f64), x: f64, y: f64) -> (f64, f64) {
    let (x0, y0, x1, y1) = *bbox;
    let (w, h) = (g.width as f64, g.height as f64);
    let u = ((x - x0) / (x1 - x0) * w - 0.5).clamp(0.0, w - 1.0);
    let v = ((y1 - y) / (y1 - y0) * h - 0.5).clamp(0.0, h - 1.0);
    (u, v)
}

/// The picture's luminance at `(x, y)`: the image stretched over `bbox` (its top row at the
/// top, y up), bilinear between pixel centres, the edge pixels held beyond them.
fn bilinear(g: &Grey, bbox: &(f64, f64, f64, f64), x: f64, y: f64) -> f64 {
    let (u, v) = blend_uv(g, bbox, x, y);
    let (i, j) = (u.floor() as usize, v.floor() as usize);
    let (fu, fv) = (u - i as f64, v - j as f64);
    let px = |i: usize, j: usize| {
        f64::from(
            g.luma
                .get(j.min(g.height - 1) * g.width + i.min(g.width - 1))
                .copied()
                .unwrap_or(1.0),
        )
    };
    let top = px(i, j) * (1.0 - fu) + px(i + 1, j) * fu;
    let bottom = px(i, j + 1) * (1.0 - fu) + px(i + 1, j + 1) * fu;
    top * (1.0 - fv) + bottom * fv
}

/// The densest pixel (the darkest, or the lightest when `light`) of every aligned block of
/// `2^L x 2^L` pixels, level by level (level 0 the pixels themselves, shared with the picture
/// rather than copied: a picture of 64 million pixels would take 256 MB more), for range
/// queries in constant time.
pub(super) struct Pyramid {
    /// Whether the densest pixel is the lightest.
    light: bool,
    /// Level 0: the picture.
    grey: Arc<Grey>,
    /// Levels 1 and up: width and height in blocks, and the densest pixel block by block, row
    /// by row.
    levels: Vec<(usize, usize, Vec<f32>)>,
}

impl Pyramid {
    /// The pyramid of `g`, up to a single block; its densest pixels are the lightest when
    /// `light`.
    pub(super) fn new(g: Arc<Grey>, light: bool) -> Self {
        let mut p = Pyramid {
            light,
            grey: g,
            levels: Vec::new(),
        };
        while let Some((w, h, prev)) = p.level(p.levels.len()).filter(|(w, h, _)| *w > 1 || *h > 1) {
            let (nw, nh) = (w.div_ceil(2), h.div_ceil(2));
            let mut next = Vec::with_capacity(nw * nh);
            for j in 0..nh {
                for i in 0..nw {
                    let block = [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(di, dj)| (2 * i + di, 2 * j + dj));
                    let values = block
                        .iter()
                        .filter(|(x, y)| x < &w && y < &h)
                        .filter_map(|(x, y)| prev.get(y * w + x));
                    next.push(Self::densest(light, values.copied()));
                }
            }
            p.levels.push((nw, nh, next));
        }
        p
    }

    /// Level `l`: its width and height in blocks and its blocks, row by row.
    fn level(&self, l: usize) -> Option<(usize, usize, &[f32])> {
        match l.checked_sub(1) {
            None => Some((self.grey.width.max(1), self.grey.height.max(1), &self.grey.luma)),
            Some(k) => self.levels.get(k).map(|(w, h, v)| (*w, *h, v.as_slice())),
        }
    }

    /// The densest of `values` (darkest, or lightest when `light`); the densest possible when
    /// there is none.
    fn densest(light: bool, values: impl Iterator<Item = f32>) -> f32 {
        if light {
            values.fold(f32::NEG_INFINITY, f32::max).max(0.0)
        } else {
            values.fold(f32::INFINITY, f32::min).min(1.0)
        }
    }

    /// The densest pixel among columns `i0..=i1` and rows `j0..=j1` (clamped to the picture),
    /// or among a few more around them.
    pub(super) fn range(&self, i0: usize, i1: usize, j0: usize, j1: usize) -> f32 {
        // The finest level where the range's ends fall in the same or neighbouring blocks:
        // blocks as wide as the range always do, and half as wide often.
        let span = i1.saturating_sub(i0).max(j1.saturating_sub(j0));
        let mut level = if span <= 1 {
            0
        } else {
            (usize::BITS - (span - 1).leading_zeros()) as usize - 1
        };
        if (i1 >> level) > (i0 >> level) + 1 || (j1 >> level) > (j0 >> level) + 1 {
            level += 1;
        }
        let level = level.min(self.levels.len());
        let Some((w, h, blocks)) = self.level(level) else {
            return if self.light { 1.0 } else { 0.0 };
        };
        let (bi0, bi1) = ((i0 >> level).min(w - 1), (i1 >> level).min(w - 1));
        let (bj0, bj1) = ((j0 >> level).min(h - 1), (j1 >> level).min(h - 1));
        let pick = |k: usize| blocks.get(k).copied();
        let corners = [bj0 * w + bi0, bj0 * w + bi1, bj1 * w + bi0, bj1 * w + bi1];
        Self::densest(self.light, corners.into_iter().filter_map(pick))
    }
}

/// The run's `--density` as a field: noise gets the fill's seed, and a period of the region's
/// size when the fill is periodic; a picture covers the region's bounding box.
pub(super) fn field(a: &FillRun, region: &Region<'_>) -> Result<Option<Field>, CliError> {
    let Some(field) = plain_field(a, region)? else { return Ok(None) };
    // A wallpaper's torus is sheared by its lattice: the field is read along it.
    Ok(Some(match region.wallpaper() {
        Some(w) => {
            let (ax, bx, by) = w.lattice();
            Field::Lattice {
                field: Box::new(field),
                ax,
                shear: bx / by,
            }
        }
        None => field,
    }))
}

/// The run's `--density` over the region's bounding box.
fn plain_field(a: &FillRun, region: &Region<'_>) -> Result<Option<Field>, CliError> {
    let Some(d) = &a.density else { return Ok(None) };
    Ok(Some(match *d {
        DensitySpec::Noise {
            kind,
            scale,
            octaves,
            gain,
            contrast,
        } => {
            let period = match (&a.region, a.periodic, region.wallpaper()) {
                (_, _, Some(w)) => {
                    let (ax, _, by) = w.lattice();
                    Some((ax, by))
                }
                (crate::model::region::RegionSpec::Rect { width, height }, true, _) => Some((*width, *height)),
                _ => None,
            };
            // As many lattice cells across the region as a periodic noise may have (2^40 at
            // the finest octave): beyond that the lattice's coordinates lose their integer
            // precision and the noise is no longer noise.
            let (x0, y0, x1, y1) = region.bbox();
            let across = (x1 - x0).max(y1 - y0) / scale * f64::from(1u32 << octaves.saturating_sub(1).min(31));
            if across.is_nan() || across > MAX_NOISE_CELLS {
                return Err(CliError::arg(
                    "--density",
                    format!(
                        "a SCALE of {} mm puts more than 2^40 lattice cells across the region at the finest octave; choose a larger SCALE or fewer OCTAVES",
                        crate::error::num(scale)
                    ),
                ));
            }
            let noise = zetafill::Noise::new(kind, a.seed, scale, octaves, gain, period)
                .map_err(|e| CliError::arg("--density", format!("{e}: choose a larger SCALE or fewer OCTAVES")))?;
            Field::Noise { noise, contrast }
        }
        DensitySpec::Image { invert, gamma, floor, .. } => {
            let Some(grey) = a.picture.clone() else {
                return Err(CliError::Io("internal: the --density picture was not read".into()));
            };
            Field::Picture {
                pyramid: Pyramid::new(grey.clone(), invert),
                grey,
                bbox: region.bbox(),
                invert,
                gamma,
                floor,
            }
        }
    }))
}

/// Points per side of the grid on which a noise density is looked at when nothing could be
/// placed (a noise has no bound below 1, so only a look can tell that it is zero).
const NOISE_GRID: usize = 256;

/// Refuses, naming `--density`, a density that is zero over the whole region, where no
/// shape can ever go: exactly for a picture (its densest pixel, from the pyramid), before the
/// fill; for noise, after a fill that placed nothing, when it is zero at every point of a
/// grid over the region (`after_halt`; before one, noise is taken as able to place).
pub(super) fn refuse_zero(field: &Field, region: &Region<'_>, after_halt: bool) -> Result<(), CliError> {
    use zetafill::Density;
    let (x0, y0, x1, y1) = region.bbox();
    match field {
        Field::Lattice { field: inner, .. } => match **inner {
            // A picture: its densest pixel, over the cell it covers.
            Field::Picture { .. } => refuse_zero(inner, region, after_halt),
            // Noise: looked at where the fill is.
            _ => refuse_zero_noise(field, inner, region, after_halt),
        },
        Field::Picture { invert, floor, .. } => {
            if field.max_over(x0, y0, x1, y1) > 0.0 {
                return Ok(());
            }
            let (none, add) = if *invert {
                ("no light pixel", "use a picture with light areas, or drop invert")
            } else {
                ("no dark pixel", "use a picture with dark areas, or add invert")
            };
            Err(CliError::arg(
                "--density",
                format!(
                    "the picture has {none}, so the density is zero everywhere (floor={floor}) and no shape can go anywhere; {add}, or raise floor=F above 0"
                ),
            ))
        }
        Field::Noise { .. } => refuse_zero_noise(field, field, region, after_halt),
    }
}

/// [`refuse_zero`] for a noise (`noise`) read as `field`.
fn refuse_zero_noise(field: &Field, noise: &Field, region: &Region<'_>, after_halt: bool) -> Result<(), CliError> {
    use zetafill::Density;
    let (x0, y0, x1, y1) = region.bbox();
    match noise {
        Field::Noise { contrast, .. } => {
            if !after_halt {
                return Ok(());
            }
            let n = NOISE_GRID as f64;
            let positive = (0..NOISE_GRID).any(|j| {
                let y = y0 + (y1 - y0) * (j as f64 + 0.5) / n;
                (0..NOISE_GRID).any(|i| field.at(x0 + (x1 - x0) * (i as f64 + 0.5) / n, y) > 0.0)
            });
            if positive {
                return Ok(());
            }
            Err(CliError::arg(
                "--density",
                format!(
                    "the noise never rises above {} (0.5 - 0.5 / CONTRAST) over the region, so the density is zero at every one of {} points looked at and no shape found a place; lower its CONTRAST ({contrast})",
                    0.5 - 0.5 / contrast,
                    NOISE_GRID * NOISE_GRID
                ),
            ))
        }
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use zetafill::Density;

    /// A picture of `w` by `h` pixels whose luminance comes from `f(i, j)`.
    fn picture(w: usize, h: usize, f: impl Fn(usize, usize) -> f32) -> Arc<Grey> {
        Arc::new(Grey {
            width: w,
            height: h,
            luma: (0..w * h).map(|k| f(k % w, k / w)).collect(),
            sha256: String::new(),
        })
    }

    fn field_of(grey: Arc<Grey>, bbox: (f64, f64, f64, f64), invert: bool, gamma: f64, floor: f64) -> Field {
        Field::Picture {
            pyramid: Pyramid::new(grey.clone(), invert),
            grey,
            bbox,
            invert,
            gamma,
            floor,
        }
    }

    /// A small generator for the test's boxes.
    fn next(state: &mut u64) -> f64 {
        *state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (*state >> 11) as f64 / (1u64 << 53) as f64
    }

    /// The bound is never below the density at any point of the box (sampled densely), and it
    /// is tight where the picture is flat; a bound taken from the box's corners alone misses
    /// dark pixels inside (the check can fail).
    #[test]
    fn the_bound_holds_over_every_box() {
        let grey = picture(37, 23, |i, j| {
            (((i * 7 + j * 13) % 17) as f32 / 16.0).min(if i == 20 && j == 9 { 0.0 } else { 1.0 })
        });
        let bbox = (-5.0, 2.0, 69.0, 48.0);
        let mut state = 1;
        for (invert, gamma, floor) in [(false, 1.0, 0.0), (true, 2.2, 0.1), (false, 0.5, 0.0)] {
            let f = field_of(grey.clone(), bbox, invert, gamma, floor);
            let mut corners_missed = false;
            for _ in 0..400 {
                let (a, b) = (-8.0 + 80.0 * next(&mut state), -8.0 + 80.0 * next(&mut state));
                let (c, d) = (0.0 + 50.0 * next(&mut state), 0.0 + 50.0 * next(&mut state));
                let (x0, x1, y0, y1) = (a.min(b), a.max(b), c.min(d), c.max(d));
                let bound = f.max_over(x0, y0, x1, y1);
                let mut top = 0f64;
                for s in 0..=40 {
                    for t in 0..=40 {
                        let (x, y) = (x0 + (x1 - x0) * f64::from(s) / 40.0, y0 + (y1 - y0) * f64::from(t) / 40.0);
                        top = top.max(f.at(x, y));
                    }
                }
                assert!(top <= bound, "{top} above {bound} over {x0} {y0} {x1} {y1}");
                let corners = [f.at(x0, y0), f.at(x1, y0), f.at(x0, y1), f.at(x1, y1)]
                    .into_iter()
                    .fold(0.0, f64::max);
                corners_missed |= corners < top;
            }
            assert!(corners_missed, "the corners alone never missed a darker pixel");
        }
        // Flat: exact (up to the margin).
        let flat = field_of(picture(8, 8, |_, _| 0.25), (0.0, 0.0, 8.0, 8.0), false, 1.0, 0.0);
        let b = flat.max_over(1.0, 1.0, 3.0, 5.0);
        assert!((b - 0.75).abs() < 1e-9, "{b}");
        // White with no floor: no density at all.
        let white = field_of(picture(8, 8, |_, _| 1.0), (0.0, 0.0, 8.0, 8.0), false, 1.0, 0.0);
        assert_eq!(white.max_over(0.0, 0.0, 8.0, 8.0), 0.0);
    }

    #[test]
    fn the_pyramid_finds_the_extremes_of_a_range() {
        let grey = picture(13, 9, |i, j| ((i * 31 + j * 17) % 101) as f32 / 100.0);
        let (dark, light) = (Pyramid::new(grey.clone(), false), Pyramid::new(grey.clone(), true));
        let mut state = 7;
        let mut exact = 0;
        for _ in 0..500 {
            let (a, b) = ((next(&mut state) * 13.0) as usize, (next(&mut state) * 13.0) as usize);
            let (c, d) = ((next(&mut state) * 9.0) as usize, (next(&mut state) * 9.0) as usize);
            let (i0, i1, j0, j1) = (a.min(b), a.max(b), c.min(d), c.max(d));
            let (lo, hi) = (dark.range(i0, i1, j0, j1), light.range(i0, i1, j0, j1));
            let pixels: Vec<f32> = (j0..=j1)
                .flat_map(|j| (i0..=i1).map(move |i| (i, j)))
                .map(|(i, j)| grey.luma[j * 13 + i])
                .collect();
            let (min, max) = pixels.iter().fold((1f32, 0f32), |(a, b), &l| (a.min(l), b.max(l)));
            assert!(lo <= min && hi >= max, "{lo} {hi} against {min} {max}");
            exact += usize::from(lo == min && hi == max);
        }
        // Mostly the range itself: a pyramid that answered with the whole picture would fail.
        assert!(exact > 100, "{exact} of 500 exact");
    }
}
