//! The shapes that can be placed: how area maps to scale, bounding radius, extents, and the
//! concrete [`Geo`] that is both tested and drawn.
//!
//! A placed shape is stored compactly as [`Placed`]: centre, scale and angle. The scale is the
//! circle's radius, or a rectangle's half height (its half width is `aspect` times that; a
//! square has aspect 1).

use crate::geom::{Geo, Point};
use crate::scalar::Scalar;

/// A kind of shape, with its fixed proportions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShapeKind {
    /// A disc.
    Circle,
    /// A square.
    Square,
    /// A rectangle whose width is `aspect` times its height.
    Rect {
        /// Width over height, finite and > 0.
        aspect: f64,
    },
}

/// A shape as stored by the engine. `Placed::default()` is an empty slot for storage.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Placed<S> {
    /// Centre x.
    pub x: S,
    /// Centre y.
    pub y: S,
    /// Scale: radius (circle) or half height (square, rectangle).
    pub scale: S,
    /// Rotation in radians, counter-clockwise (0 when unrotated).
    pub angle: S,
    /// Index of the kind in the engine's shape list.
    pub kind: u8,
}

impl ShapeKind {
    /// Whether the proportions are valid (finite aspect > 0).
    pub fn is_valid(&self) -> bool {
        match *self {
            ShapeKind::Rect { aspect } => aspect.is_finite() && aspect > 0.0,
            _ => true,
        }
    }

    /// Whether rotating the shape changes it.
    pub fn rotates(&self) -> bool {
        !matches!(self, ShapeKind::Circle)
    }

    fn aspect(&self) -> f64 {
        match *self {
            ShapeKind::Rect { aspect } => aspect,
            _ => 1.0,
        }
    }

    /// The scale for an area.
    pub fn scale_for_area(&self, area: f64) -> f64 {
        match self {
            ShapeKind::Circle => crate::scalar::sqrtf(area / core::f64::consts::PI),
            _ => crate::scalar::sqrtf(area / (4.0 * self.aspect())),
        }
    }

    /// The area of the shape at a scale.
    pub fn area_for_scale(&self, scale: f64) -> f64 {
        match self {
            ShapeKind::Circle => core::f64::consts::PI * scale * scale,
            _ => 4.0 * self.aspect() * scale * scale,
        }
    }

    /// Half width and half height at a scale.
    fn half_sides<S: Scalar>(&self, scale: S) -> (S, S) {
        (scale * S::from_f64(self.aspect()), scale)
    }

    /// Radius of the smallest circle about the centre that holds the shape.
    pub fn bounding_radius<S: Scalar>(&self, scale: S) -> S {
        match self {
            ShapeKind::Circle => scale,
            _ => {
                let (hw, hh) = self.half_sides(scale);
                (hw * hw + hh * hh).sqrt()
            }
        }
    }

    /// Radius of the largest circle about the centre inside the shape.
    pub fn inradius<S: Scalar>(&self, scale: S) -> S {
        match self {
            ShapeKind::Circle => scale,
            _ => {
                let (hw, hh) = self.half_sides(scale);
                hw.min(hh)
            }
        }
    }

    /// The narrowest width of the shape (the size `--min-size` compares against).
    pub fn min_width(&self, scale: f64) -> f64 {
        2.0 * self.inradius(scale)
    }

    /// The sine and cosine the shape uses for an angle (exactly 0 and 1 for angle 0).
    pub fn sin_cos<S: Scalar>(angle: S) -> (S, S) {
        if angle == S::ZERO {
            (S::ZERO, S::ONE)
        } else {
            angle.sin_cos()
        }
    }

    /// Half extents (x, y) of the shape's bounding box at a rotation given by its sine and
    /// cosine; the box about the centre that holds the shape (up to rounding: the exact
    /// containment test is always made on the [`Geo`]).
    pub fn half_extents<S: Scalar>(&self, scale: S, sin: S, cos: S) -> (S, S) {
        match self {
            ShapeKind::Circle => (scale, scale),
            _ => {
                let (hw, hh) = self.half_sides(scale);
                let (s, c) = (sin.abs(), cos.abs());
                (hw * c + hh * s, hw * s + hh * c)
            }
        }
    }

    /// The concrete shape at a place.
    pub fn geo<S: Scalar>(&self, c: Point<S>, scale: S, angle: S) -> Geo<S> {
        let (sin, cos) = Self::sin_cos(angle);
        self.geo_sc(c, scale, sin, cos)
    }

    /// The concrete shape at a place, rotation given by [`ShapeKind::sin_cos`] of its angle.
    pub fn geo_sc<S: Scalar>(&self, c: Point<S>, scale: S, sin: S, cos: S) -> Geo<S> {
        match self {
            ShapeKind::Circle => Geo::Circle { c, r: scale },
            _ => {
                let (hw, hh) = self.half_sides(scale);
                let corner = |sx: S, sy: S| {
                    let (dx, dy) = (sx * hw, sy * hh);
                    Point::new(c.x + dx * cos - dy * sin, c.y + dx * sin + dy * cos)
                };
                let (m, p) = (-S::ONE, S::ONE);
                Geo::Convex { v: [corner(m, m), corner(p, m), corner(p, p), corner(m, p)], n: 4 }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn area_and_scale_round_trip() {
        for k in [ShapeKind::Circle, ShapeKind::Square, ShapeKind::Rect { aspect: 2.5 }] {
            let s = k.scale_for_area(123.0);
            assert!((k.area_for_scale(s) - 123.0).abs() < 1e-12);
        }
    }

    #[test]
    fn rotated_square_is_ccw_and_has_right_area() {
        let g = ShapeKind::Square.geo(Point::new(1.0, 2.0), 0.5f64, 0.7);
        let v = g.vertices();
        let mut a2 = 0.0;
        for i in 0..4 {
            let (p, q) = (v[i], v[(i + 1) % 4]);
            a2 += p.x * q.y - q.x * p.y;
        }
        assert!((a2 / 2.0 - 1.0).abs() < 1e-12);
    }
}
