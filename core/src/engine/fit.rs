//! What a placement needs that stays fixed over its trials ([`NextShape`]: kind, area,
//! scale, centre range), and the shapes that certainly cannot lie in the region in any
//! orientation (reported as [`StepError::CannotFit`] instead of halting after the trial
//! limit).

use super::Engine;
use crate::feasibility::too_large;
use crate::geom::Point;
use crate::params::StepError;
use crate::region::Region;
use crate::scalar::Scalar;
use crate::shape::ShapeKind;

/// What a placement needs that stays fixed over its trials.
#[derive(Clone, Copy, Debug)]
pub(super) struct NextShape<S> {
    pub(super) index: u64,
    pub(super) kind: ShapeKind,
    pub(super) area: f64,
    pub(super) base_scale: S,
    pub(super) base_r: S,
    pub(super) rotated: bool,
    pub(super) is_blob: bool,
    /// The radius of the inscribed disc at the base scale ([`ShapeKind::solid_radius`]).
    pub(super) base_solid: Option<S>,
    /// The centre range (x0, x1, y0, y1).
    pub(super) range: (S, S, S, S),
}

impl<S: Scalar> Engine<'_, S> {
    /// Whether a shape of this area certainly cannot lie in the region in any orientation.
    /// Kept out of line: its scratch geometry would otherwise sit in every step's stack frame.
    #[inline(never)]
    pub(super) fn cannot_fit(&self, kind: ShapeKind, area: f64) -> bool {
        let scale: S = kind.scale_for(area, S::ZERO);
        let inr = kind.inradius(scale);
        if self.region.centre_range(inr, inr, self.gap).is_none() {
            return true;
        }
        match self.region {
            Region::Rect {
                periodic: false,
                width,
                height,
            } => {
                // Rectangles: the narrowest bounding boxes are at 0 and 90 degrees (or only at
                // 0 when unrotated); every other kind is tested at angle 0 and reported only if
                // its inscribed circle cannot fit (above).
                if !matches!(
                    kind,
                    ShapeKind::Square | ShapeKind::Rect { .. } | ShapeKind::Circle | ShapeKind::Ring { .. }
                ) {
                    return false;
                }
                let quarter = S::from_f64(core::f64::consts::FRAC_PI_2);
                let angles: &[S] = if self.params.rotate && kind.rotates() {
                    &[S::ZERO, quarter]
                } else {
                    &[S::ZERO]
                };
                let (w, h) = (S::from_f64(width), S::from_f64(height));
                !angles.iter().any(|&a| {
                    let (x0, y0, x1, y1) = kind.geo_in(self.motifs, Point::new(S::ZERO, S::ZERO), scale, a).bounds();
                    x1 - x0 + self.gap + self.gap <= w && y1 - y0 + self.gap + self.gap <= h
                })
            }
            Region::Rect { periodic: true, .. } => {
                matches!(kind, ShapeKind::Circle | ShapeKind::Ring { .. })
                    && self.self_overlaps(&kind.geo_in(self.motifs, Point::new(S::ZERO, S::ZERO), scale, S::ZERO), scale)
            }
            // A regular shape's smallest enclosing circle is its circumcircle (a blob's is not
            // known, so only its inscribed circle is used).
            Region::Circle { radius } => {
                let r = if kind.is_blob() {
                    kind.inradius(scale)
                } else {
                    kind.bounding_radius(scale)
                };
                r + self.gap > S::from_f64(radius)
            }
            Region::Annulus { outer, inner } => {
                // In the band, or (a ring) around the hole.
                let band = S::from_f64(outer - inner);
                let in_band = inr + inr + self.gap + self.gap <= band;
                let around = match kind {
                    ShapeKind::Ring { inner: ri } => {
                        scale * S::from_f64(ri) >= S::from_f64(inner) + self.gap && scale + self.gap <= S::from_f64(outer)
                    }
                    _ => false,
                };
                !(in_band || around)
            }
            Region::Polygon(_) => false,
            Region::Wallpaper(_) => self.wider_than_lattice(inr),
        }
    }

    /// What the next placement needs that stays fixed over its trials, or why it cannot be
    /// made.
    pub(super) fn next_shape(&self) -> Result<NextShape<S>, StepError> {
        if self.len + self.per().get() > self.shapes.len() {
            return Err(StepError::Capacity {
                capacity: (self.shapes.len() / self.per()) as u64,
            });
        }
        self.shape_at(self.orbits() as u64)
    }

    /// [`Engine::next_shape`] for placement `index`, whether or not the storage has room for
    /// it.
    pub(super) fn shape_at(&self, index: u64) -> Result<NextShape<S>, StepError> {
        let kind = self.kind_of(index);
        let area = self.area_of(index);
        // Below the scalar's resolution the exact tests are not exact, and on f64 a polygon's
        // vertices round onto each other where the coordinates are large.
        let scale = kind.scale_for_area(area);
        if kind.min_width(scale) < self.min_size {
            return Err(StepError::TooSmall { index });
        }
        let base_scale: S = kind.scale_for(area, S::ZERO);
        if !(base_scale > S::ZERO && base_scale.is_finite()) || self.cannot_fit(kind, area) {
            return Err(StepError::CannotFit { index });
        }
        // Wider than the scalar computes exactly: its squared lengths would saturate (f64 has
        // no limit). Only a torus lets such a shape in; any other region refused it above.
        if too_large::<S>(kind, area) {
            return Err(StepError::TooLarge { index });
        }
        let rotated = self.params.rotate && kind.rotates();
        let is_blob = kind.is_blob();
        // The centre is drawn uniformly over the positions where the shape can lie inside the
        // region's bounding box: for an unrotated shape its exact extents set the range; a
        // rotated one may lie anywhere its inscribed circle fits, and the exact containment
        // test decides. So accepted placements are uniform over all valid (position, angle)
        // pairs.
        let (ex, ey) = if rotated || is_blob {
            let inr = kind.inradius(base_scale);
            (inr, inr)
        } else {
            let (x0, y0, x1, y1) = kind.geo_in(self.motifs, Point::new(S::ZERO, S::ZERO), base_scale, S::ZERO).bounds();
            ((-x0).max(x1), (-y0).max(y1))
        };
        let range = self
            .region
            .centre_range(ex, ey, self.gap)
            .unwrap_or((S::ZERO, S::ZERO, S::ZERO, S::ZERO));
        Ok(NextShape {
            index,
            kind,
            area,
            base_scale,
            base_r: kind.bounding_radius(base_scale),
            rotated,
            is_blob,
            base_solid: kind.solid_radius(base_scale),
            range,
        })
    }
}
