//! Colours (Sugihara section 5): the graph distance of every site from its territory's seed
//! (Procedure 2: breadth-first search over Delaunay edges inside the territory), and the HSB
//! colour x' = c^k + D d^k with the paper's rules to bring x' back into the unit cube: the hue
//! wraps (eq. 11), saturation and brightness are clamped (eqs. 12, 13).

use super::model::Tri;
use crate::geometry::voronoi::neighbours;
use std::collections::VecDeque;
use zetafill::internals::rng::uniform;
use zetafill::ZetaRng;

/// A territory's colour rule: the seed's colour c^k and the step d^k per unit of distance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rule {
    /// c^k = (hue, saturation, brightness), each in [0, 1].
    pub c: [f64; 3],
    /// d^k, any finite numbers.
    pub d: [f64; 3],
}

/// Eq. (11): the hue wraps. x < 0 gives the fractional part of 1 - |x|; 0 <= x <= 1 is kept
/// (so 1 stays 1, the same red as 0); x > 1 gives its fractional part. The fractional part of
/// y is y - floor(y), which is what keeps the result in [0, 1) when 1 - |x| is itself negative.
pub fn wrap_hue(x: f64) -> f64 {
    let frac = |y: f64| y - y.floor();
    if x < 0.0 {
        frac(1.0 - x.abs())
    } else if x <= 1.0 {
        x
    } else {
        frac(x)
    }
}

/// Eqs. (12), (13): saturation and brightness are clamped to [0, 1].
pub fn clamp_unit(x: f64) -> f64 {
    x.clamp(0.0, 1.0)
}

/// The colour of a site at distance `dist` from its seed: eqs. (10)-(13).
pub fn colour(rule: &Rule, dist: u32) -> [f64; 3] {
    let dd = f64::from(dist);
    let x = [rule.c[0] + dd * rule.d[0], rule.c[1] + dd * rule.d[1], rule.c[2] + dd * rule.d[2]];
    [wrap_hue(x[0]), clamp_unit(x[1]), clamp_unit(x[2])]
}

/// Procedure 2 for every territory: the distance of each site from its seed, counted in
/// Delaunay edges inside the territory. Seeds are sites `0..k`. A site its seed cannot reach
/// (never, once connectivity is kept) gets `u32::MAX`.
pub fn distances(tri: &Tri, territory: &[u32], k: usize) -> Vec<u32> {
    let mut dist = vec![u32::MAX; territory.len()];
    let mut queue = VecDeque::new();
    for (s, d) in dist.iter_mut().enumerate().take(k) {
        *d = 0;
        queue.push_back(s);
    }
    // One multi-source search: a site is only ever entered from its own territory, so each
    // territory's distances are those of its own seed.
    while let Some(v) = queue.pop_front() {
        let next = dist[v] + 1;
        for w in neighbours(tri, v) {
            if territory[w] == territory[v] && dist[w] == u32::MAX {
                dist[w] = next;
                queue.push_back(w);
            }
        }
    }
    dist
}

/// A random rule for a territory whose sites lie up to `max_dist` from the seed: hue uniform
/// in [0, 1), saturation in [0.35, 0.95), brightness in [0.55, 1); the step d^k has a hue
/// component in [-1, 1) / max_dist (at most one turn of the colour wheel across the
/// territory) and saturation and brightness components in [-0.5, 0.5) / max_dist. Draws six
/// unit values in that order.
pub fn random_rule(rng: &mut ZetaRng, max_dist: u32) -> Rule {
    let c = [uniform(rng, 0.0, 1.0), uniform(rng, 0.35, 0.95), uniform(rng, 0.55, 1.0)];
    let span = f64::from(max_dist.max(1));
    let d = [
        uniform(rng, -1.0, 1.0) / span,
        uniform(rng, -0.5, 0.5) / span,
        uniform(rng, -0.5, 0.5) / span,
    ];
    Rule { c, d }
}

/// HSB (hue, saturation, brightness in [0, 1]) to 8-bit RGB.
pub fn hsb_to_rgb(hsb: [f64; 3]) -> [u8; 3] {
    let [h, s, v] = hsb;
    let h6 = (h - h.floor()) * 6.0;
    let sector = (h6.floor() as i64).rem_euclid(6);
    let f = h6 - h6.floor();
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f)));
    let (r, g, b) = match sector {
        0 => (v, t, p),
        1 => (q, v, p),
        2 => (p, v, t),
        3 => (p, q, v),
        4 => (t, p, v),
        _ => (v, p, q),
    };
    let byte = |x: f64| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
    [byte(r), byte(g), byte(b)]
}

/// `#rrggbb` for an HSB colour.
pub fn hex(hsb: [f64; 3]) -> String {
    let [r, g, b] = hsb_to_rgb(hsb);
    format!("#{r:02x}{g:02x}{b:02x}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hue_wraps_at_its_edges() {
        assert_eq!(wrap_hue(0.0), 0.0);
        assert_eq!(wrap_hue(1.0), 1.0);
        assert_eq!(wrap_hue(0.25), 0.25);
        assert!((wrap_hue(1.25) - 0.25).abs() < 1e-15);
        assert_eq!(wrap_hue(2.0), 0.0);
        assert!((wrap_hue(-0.25) - 0.75).abs() < 1e-15);
        assert!((wrap_hue(-1.25) - 0.75).abs() < 1e-15);
        assert_eq!(wrap_hue(-1.0), 0.0);
    }

    #[test]
    fn saturation_and_brightness_clamp() {
        let r = Rule {
            c: [0.9, 0.5, 0.5],
            d: [0.1, 0.2, -0.2],
        };
        assert_eq!(colour(&r, 0), [0.9, 0.5, 0.5]);
        let c3 = colour(&r, 3);
        assert!((c3[0] - 0.2).abs() < 1e-12 && c3[1] == 1.0 && c3[2] == 0.0, "{c3:?}");
    }

    #[test]
    fn hsb_primaries() {
        assert_eq!(hsb_to_rgb([0.0, 1.0, 1.0]), [255, 0, 0]);
        assert_eq!(hsb_to_rgb([1.0, 1.0, 1.0]), [255, 0, 0]);
        assert_eq!(hsb_to_rgb([1.0 / 3.0, 1.0, 1.0]), [0, 255, 0]);
        assert_eq!(hsb_to_rgb([2.0 / 3.0, 1.0, 0.5]), [0, 0, 128]);
        assert_eq!(hsb_to_rgb([0.5, 0.0, 1.0]), [255, 255, 255]);
    }
}
