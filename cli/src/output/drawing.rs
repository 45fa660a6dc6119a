//! A fill as pen strokes: the outlines (and hatching) of every shape as a
//! [`Drawing`], in the region's frame, periodic images clipped exactly to the tile. This is
//! what the G-code writer draws.

use super::hatch;
use crate::model::doc::{FillDoc, RegionDoc, ShapeDoc};
use crate::model::{clip_path, periodic_images, shape_bounds, shape_width, Bounds, Drawing, Path};

/// What goes into a drawing besides the outlines.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct BuildOptions {
    /// Leave out shapes (and ring holes) narrower than this (mm).
    pub min_feature: f64,
    /// Hatch every shape.
    pub hatch: Option<hatch::Hatch>,
    /// Draw the outlines (false: hatch only).
    pub no_outline: bool,
}

/// The outline paths of one shape (shifted by `off`).
fn shape_outlines(sh: &ShapeDoc, off: (f64, f64), min_feature: f64) -> Vec<Path> {
    let c = [sh.center[0] + off.0, sh.center[1] + off.1];
    match (sh.radius, sh.inner_radius) {
        (Some(r), inner) => {
            let mut v = vec![Path::circle(c, r)];
            if let Some(ri) = inner {
                if ri > 0.0 && 2.0 * ri >= min_feature {
                    v.push(Path::circle(c, ri));
                }
            }
            v
        }
        _ => {
            let vs = sh.vertices.as_deref().unwrap_or(&[]);
            if vs.len() < 2 {
                return vec![];
            }
            vec![Path::polyline(vs.iter().map(|v| [v[0] + off.0, v[1] + off.1]).collect(), true)]
        }
    }
}

/// The drawing of a fill in the region's frame: outlines (and hatching), shapes narrower
/// than `min_feature` left out; periodic fills clipped exactly to the tile.
pub fn from_fill(doc: &FillDoc, opt: &BuildOptions) -> Drawing {
    let tile = match doc.region {
        RegionDoc::Rect {
            width,
            height,
            periodic: true,
        } => Some(Bounds {
            x0: 0.0,
            y0: 0.0,
            x1: width,
            y1: height,
        }),
        _ => None,
    };
    let mut paths = Vec::new();
    for sh in &doc.shapes {
        if shape_width(sh) < opt.min_feature {
            continue;
        }
        let sb = shape_bounds(sh);
        let offs = match &tile {
            Some(t) => periodic_images(&sb, t.x1, t.y1),
            None => vec![(0.0, 0.0)],
        };
        for off in offs {
            let mut here = Vec::new();
            if !opt.no_outline {
                here.extend(shape_outlines(sh, off, opt.min_feature));
            }
            if let Some(h) = &opt.hatch {
                here.extend(
                    h.shape(sh, off, opt.min_feature)
                        .into_iter()
                        .map(|[a, b]| Path::polyline(vec![a, b], false)),
                );
            }
            match &tile {
                Some(t) => {
                    let inside = Bounds {
                        x0: sb.x0 + off.0,
                        y0: sb.y0 + off.1,
                        x1: sb.x1 + off.0,
                        y1: sb.y1 + off.1,
                    }
                    .inside(t, 0.0);
                    if inside {
                        paths.extend(here);
                    } else {
                        paths.extend(here.iter().flat_map(|p| clip_path(p, t)));
                    }
                }
                None => paths.extend(here),
            }
        }
    }
    Drawing { paths }
}
