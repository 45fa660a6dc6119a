//! Placement of a drawing on a page or a bed: as it is, top-left, centred or scaled to fit,
//! refused (with the sizes in the message) when it does not fit.

use super::{Bounds, Pt};

/// A uniform scale then a shift: `p -> scale * p + (dx, dy)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Scale factor (1 unless fitted).
    pub scale: f64,
    /// Shift in x.
    pub dx: f64,
    /// Shift in y.
    pub dy: f64,
}

impl Placement {
    /// No change.
    pub const IDENTITY: Placement = Placement {
        scale: 1.0,
        dx: 0.0,
        dy: 0.0,
    };

    /// Applies the placement to a point.
    pub fn apply(&self, p: Pt) -> Pt {
        [self.scale * p[0] + self.dx, self.scale * p[1] + self.dy]
    }
}

/// How a drawing is put into an area (a bed or a page, less its margins).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fit {
    /// Where it is (a bed: the region's own coordinates).
    AsIs,
    /// Its bounding box's top-left corner at the area's top-left corner (pages).
    TopLeft,
    /// Centred, unscaled.
    Center,
    /// Scaled (up or down) to the largest size that fits, centred.
    Scale,
}

/// Places `drawing` (its bounding box `b`) into `area`, or says why it does not fit.
pub fn place(b: &Bounds, area: &Bounds, fit: Fit) -> Result<Placement, String> {
    if b.is_empty() {
        return Ok(Placement::IDENTITY);
    }
    let pl = match fit {
        Fit::AsIs => Placement::IDENTITY,
        Fit::TopLeft => Placement {
            scale: 1.0,
            dx: area.x0 - b.x0,
            dy: area.y1 - b.y1,
        },
        Fit::Center => Placement {
            scale: 1.0,
            dx: (area.x0 + area.x1 - b.x0 - b.x1) / 2.0,
            dy: (area.y0 + area.y1 - b.y0 - b.y1) / 2.0,
        },
        Fit::Scale => {
            let sx = if b.width() > 0.0 { area.width() / b.width() } else { f64::INFINITY };
            let sy = if b.height() > 0.0 {
                area.height() / b.height()
            } else {
                f64::INFINITY
            };
            let s = sx.min(sy);
            if !(s.is_finite() && s > 0.0) {
                return Err("the drawing has no extent to scale".into());
            }
            Placement {
                scale: s,
                dx: (area.x0 + area.x1) / 2.0 - s * (b.x0 + b.x1) / 2.0,
                dy: (area.y0 + area.y1) / 2.0 - s * (b.y0 + b.y1) / 2.0,
            }
        }
    };
    let placed = Bounds {
        x0: pl.apply([b.x0, b.y0])[0],
        y0: pl.apply([b.x0, b.y0])[1],
        x1: pl.apply([b.x1, b.y1])[0],
        y1: pl.apply([b.x1, b.y1])[1],
    };
    if !placed.inside(area, 1e-6) {
        return Err(format!(
            "the drawing ({:.3} x {:.3} mm at {:.3}, {:.3}) does not fit the usable area ({:.3} x {:.3} mm at {:.3}, {:.3})",
            placed.width(),
            placed.height(),
            placed.x0,
            placed.y0,
            area.width(),
            area.height(),
            area.x0,
            area.y0
        ));
    }
    Ok(pl)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Bounds {
        Bounds {
            x0: 0.0,
            y0: 0.0,
            x1: 10.0,
            y1: 10.0,
        }
    }

    #[test]
    fn placement_refuses_what_does_not_fit() {
        let b = Bounds {
            x0: 0.0,
            y0: 0.0,
            x1: 20.0,
            y1: 5.0,
        };
        assert!(place(&b, &unit(), Fit::AsIs).is_err());
        assert!(place(&b, &unit(), Fit::Center).is_err());
        let pl = place(&b, &unit(), Fit::Scale).unwrap_or(Placement::IDENTITY);
        assert_eq!(pl.scale, 0.5);
        assert_eq!(pl.apply([0.0, 0.0]), [0.0, 3.75]);
    }
}
