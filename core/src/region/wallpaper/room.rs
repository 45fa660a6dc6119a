//! The room a point keeps from its own orbit, and the largest disc that clears its orbit
//! somewhere: what the up-front check of a symmetric fill's first shape compares against.

use super::Wallpaper;
use crate::geom::Point;

impl Wallpaper {
    /// The distance from `p` to the nearest other point of its orbit: its images under every
    /// operation and lattice translation, the point itself excluded.
    pub fn orbit_gap(&self, p: Point<f64>) -> f64 {
        let (ax, bx, by) = (self.ax, self.bx, self.by);
        let mut best = f64::INFINITY;
        for k in 0..self.order() {
            let Some(iso) = self.iso(k) else { continue };
            let [a, b, c, d] = iso.m;
            let q = Point::new(a * p.x + b * p.y + iso.t[0], c * p.x + d * p.y + iso.t[1]);
            // The difference, reduced to the lattice's nearest copies.
            let mut e = self.wrap(Point::new(q.x - p.x, q.y - p.y));
            if e.x > ax / 2.0 {
                e.x -= ax;
            }
            for l in -2i32..=2 {
                for n in -2i32..=2 {
                    if k == 0 && l == 0 && n == 0 {
                        continue;
                    }
                    let x = e.x + f64::from(n) * ax + f64::from(l) * bx;
                    let y = e.y + f64::from(l) * by;
                    // (An operation that fixes the point leaves it no room at all.)
                    best = best.min(libm::sqrt(x * x + y * y));
                }
            }
        }
        best
    }

    /// The radius of the largest disc that clears its own orbit somewhere: half the most
    /// room any point keeps from the other points of its orbit, found by a grid over the
    /// domain and a pattern search from its best points (the disc at the point found clears
    /// it; no point was seen to do better).
    pub fn largest_disc(&self) -> f64 {
        const GRID: usize = 48;
        let (ax, bx, by) = (self.ax, self.bx, self.by);
        let at = |u: f64, v: f64| Point::new(u * ax + v * bx, v * by);
        let mut top = [(f64::NEG_INFINITY, 0.0, 0.0); 8];
        for i in 0..GRID {
            for j in 0..GRID {
                let (u, v) = ((i as f64 + 0.5) / GRID as f64, (j as f64 + 0.5) / GRID as f64);
                let g = self.orbit_gap(at(u, v));
                // Keep the eight best in place of the worst kept.
                if let Some(w) = top.iter_mut().min_by(|a, b| a.0.total_cmp(&b.0)) {
                    if g > w.0 {
                        *w = (g, u, v);
                    }
                }
            }
        }
        let mut best = 0.0f64;
        for &(g0, u0, v0) in &top {
            let (mut g, mut u, mut v) = (g0, u0, v0);
            let mut step = 1.0 / GRID as f64;
            while step > 1e-13 {
                let mut moved = false;
                for (du, dv) in [
                    (1.0, 0.0),
                    (-1.0, 0.0),
                    (0.0, 1.0),
                    (0.0, -1.0),
                    (1.0, 1.0),
                    (-1.0, -1.0),
                    (1.0, -1.0),
                    (-1.0, 1.0),
                ] {
                    let (nu, nv) = (u + du * step, v + dv * step);
                    let ng = self.orbit_gap(at(nu, nv));
                    if ng > g {
                        (g, u, v, moved) = (ng, nu, nv, true);
                    }
                }
                if !moved {
                    step /= 2.0;
                }
            }
            best = best.max(g);
        }
        best / 2.0
    }
}
