//! The scale-periodic tile of the "Fractal Tiles" post: discs in a W x H tile that matches
//! itself left and right, two half-scale copies of itself along its top, and (as one of the
//! halves) a double-scale copy along its bottom. Its parameters and the copies of the plane
//! around it are [`TileSpec`] ([`crate::model::tile`]); this module grows it.
//!
//! ## The plane the tile lives in
//! Row 0 is the tile repeated with period W over `0 <= y < H`; row r is the tile scaled by
//! `2^-r`, repeated with period `W 2^-r` over `2H (1 - 2^-r) <= y < 2H (1 - 2^-(r+1))`. So row
//! 1 (half scale) sits on top of row 0, and row 0 on top of row -1 (double scale), each tile
//! of row -1 carrying two of row 0. The rows pile up towards the line `y = 2H`.
//!
//! Disc size and spacing vary with y by a factor of two over the tile (as in the post): a disc
//! centred at height y has radius `R f(y)`, and two discs keep a gap of `S f(ym)` (ym the
//! mean height of their centres), with `f(y) = 1 - y / 2H`. That f is the one that makes the
//! plane self-similar: the half-scale map `y -> H + y/2` halves it, `f(H + y/2) = f(y) / 2`,
//! so every row is the same texture at its own scale, and an exponential law would not be.
//!
//! ## Placement (the post's)
//! A try picks a uniform point of the tile, takes the radius of its height, and keeps the disc
//! when it clears every disc already placed *in every copy of the tile that can reach it*: the
//! neighbours left and right in row 0, the half-scale copies above, and the double-scale copy
//! below in both of its configurations (the tile is the left half of one and the right half of
//! the next). Nothing that could reach across two rows is allowed (the radius and spacing are
//! limited to a quarter of the tile), so those copies are all of them, and no two discs
//! overlap anywhere in the plane. The loop stops after a given number of tries.
//!
//! ## Doppelgangers (the post's)
//! The tile's bottom edge must meet the top edge of the double-scale copy on both its halves,
//! so what crosses the tile's top edge must repeat with period W/2 along it. A disc that
//! crosses the top edge gets a twin shifted by W/2; both must fit, and both are added. For
//! Voronoi cobblestones every centre in a band at the top gets a twin, since a cell can cross
//! the edge without its disc doing so (the post uses the top quarter; the band doubles until
//! the edges crossing the top repeat with period W/2 exactly, see
//! [`seam_gaps`](super::render::seam_gaps)).

use crate::geometry::voronoi::Pt;
use crate::model::tile::{Map, TileSpec};

/// One disc of the tile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disc {
    /// Centre in the tile's frame, `[0, W) x [0, H)`.
    pub c: Pt,
    /// Radius.
    pub r: f64,
    /// The index of its doppelganger, if it has one.
    pub twin: Option<usize>,
}

/// A generated tile.
#[derive(Debug, Clone, PartialEq)]
pub struct Tile {
    /// Its parameters.
    pub spec: TileSpec,
    /// Its discs in placement order (a twin right after its disc).
    pub discs: Vec<Disc>,
    /// Tries made.
    pub tries: u64,
}

/// A disc of the plane: an image of a tile disc.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Image {
    /// Centre.
    pub c: Pt,
    /// Radius.
    pub r: f64,
    /// The tile disc it is an image of.
    pub disc: usize,
}

/// The images of the tile's discs that come within `reach` of the tile, under
/// [`TileSpec::maps`] for the picture.
pub fn images(tile: &Tile, reach: f64) -> Vec<Image> {
    let (w, h) = (tile.spec.width, tile.spec.height);
    let mut out = Vec::new();
    for m in tile.spec.maps(true) {
        for (i, d) in tile.discs.iter().enumerate() {
            let c = m.at(d.c);
            let r = m.s * d.r;
            if c[0] + r > -reach && c[0] - r < w + reach && c[1] + r > -reach && c[1] - r < h + reach {
                out.push(Image { c, r, disc: i });
            }
        }
    }
    out
}

/// A bucket grid over the images near the tile, for the tries.
struct Grid {
    x0: f64,
    y0: f64,
    cell: f64,
    nx: usize,
    ny: usize,
    buckets: Vec<Vec<Image>>,
}

impl Grid {
    fn new(spec: &TileSpec, reach: f64) -> Grid {
        let cell = (2.0 * spec.radius + spec.spacing).max(spec.width.min(spec.height) / 256.0);
        let (x0, y0) = (-reach, -reach);
        let nx = (((spec.width + 2.0 * reach) / cell).ceil() as usize).max(1);
        let ny = (((spec.height + 2.0 * reach) / cell).ceil() as usize).max(1);
        Grid {
            x0,
            y0,
            cell,
            nx,
            ny,
            buckets: vec![Vec::new(); nx * ny],
        }
    }

    fn index(&self, v: f64, v0: f64, n: usize) -> usize {
        (((v - v0) / self.cell).floor().max(0.0) as usize).min(n - 1)
    }

    fn add(&mut self, im: Image) {
        let (ix, iy) = (self.index(im.c[0], self.x0, self.nx), self.index(im.c[1], self.y0, self.ny));
        self.buckets[iy * self.nx + ix].push(im);
    }

    /// Whether a disc at `c` of radius `r` clears every image: the gap between centres at
    /// heights `c[1]` and the image's is kept. Images are at most `rmax` in radius.
    fn clear(&self, spec: &TileSpec, c: Pt, r: f64, rmax: f64, gmax: f64) -> bool {
        let q = r + rmax + gmax;
        let (ix0, ix1) = (self.index(c[0] - q, self.x0, self.nx), self.index(c[0] + q, self.x0, self.nx));
        let (iy0, iy1) = (self.index(c[1] - q, self.y0, self.ny), self.index(c[1] + q, self.y0, self.ny));
        for iy in iy0..=iy1 {
            for ix in ix0..=ix1 {
                for im in &self.buckets[iy * self.nx + ix] {
                    let need = r + im.r + spec.gap_between(c[1], im.c[1]);
                    let (dx, dy) = (c[0] - im.c[0], c[1] - im.c[1]);
                    if dx * dx + dy * dy < need * need {
                        return false;
                    }
                }
            }
        }
        true
    }
}

/// Whether disc `a` clears every copy of disc `b` under `maps`.
fn pair_clear(spec: &TileSpec, maps: &[Map], a: (Pt, f64), b: (Pt, f64)) -> bool {
    maps.iter().all(|m| {
        let (c, r) = (m.at(b.0), m.s * b.1);
        let need = a.1 + r + spec.gap_between(a.0[1], c[1]);
        let (dx, dy) = (a.0[0] - c[0], a.0[1] - c[1]);
        dx * dx + dy * dy >= need * need
    })
}

/// Grows a tile: the post's loop with the copies and doppelgangers described above.
/// Deterministic: the same spec gives the same discs.
pub fn grow(spec: &TileSpec) -> Tile {
    grow_with(spec, |_| {})
}

/// How many tries pass between two calls of the progress callback.
pub const PROGRESS_EVERY: u64 = 1 << 16;

/// [`grow`], calling `progress` with the tries made every [`PROGRESS_EVERY`] tries.
pub fn grow_with(spec: &TileSpec, mut progress: impl FnMut(u64)) -> Tile {
    let (w, h) = (spec.width, spec.height);
    // A candidate has radius at most R; an image that can touch the tile at most 2R (a disc
    // of the double-scale row near its top edge); the gap is at most S f(-reach) < 2S. So
    // images farther than `reach` from the tile cannot touch a candidate.
    let rmax = 2.0 * spec.radius;
    let reach = 3.0 * spec.radius + 2.0 * spec.spacing;
    let gmax = spec.spacing * spec.factor(-reach);
    let mut grid = Grid::new(spec, reach);
    let maps = spec.maps(false);
    // The copies of a disc other than itself (row 0 neighbours, the rows above and below).
    let others = maps.get(1..).unwrap_or(&[]);
    let mut rng = zetafill::rng_from_seed(spec.seed);
    let mut discs: Vec<Disc> = Vec::new();
    let mut tries = 0;
    let fits = |grid: &Grid, c: Pt, r: f64| grid.clear(spec, c, r, rmax, gmax) && pair_clear(spec, others, (c, r), (c, r));
    while tries < spec.tries {
        tries += 1;
        if tries % PROGRESS_EVERY == 0 {
            progress(tries);
        }
        let x = w * zetafill::internals::rng::unit::<f64, _>(&mut rng);
        let y = h * zetafill::internals::rng::unit::<f64, _>(&mut rng);
        let r = spec.radius_at(y);
        let c = [x, y];
        let twin = y + r > h || y > h * (1.0 - spec.band);
        if !fits(&grid, c, r) {
            continue;
        }
        let mut new = vec![(c, r)];
        if twin {
            let t = [(x + 0.5 * w) % w, y];
            if !fits(&grid, t, r) || !pair_clear(spec, &maps, (c, r), (t, r)) {
                continue;
            }
            new.push((t, r));
        }
        let first = discs.len();
        for (k, &(c, r)) in new.iter().enumerate() {
            let twin = (new.len() == 2).then_some(first + 1 - k);
            discs.push(Disc { c, r, twin });
            for m in &maps {
                let ci = m.at(c);
                let ri = m.s * r;
                if ci[0] + ri > -reach && ci[0] - ri < w + reach && ci[1] + ri > -reach && ci[1] - ri < h + reach {
                    grid.add(Image {
                        c: ci,
                        r: ri,
                        disc: first + k,
                    });
                }
            }
        }
    }
    Tile { spec: *spec, discs, tries }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec() -> TileSpec {
        TileSpec {
            width: 100.0,
            height: 80.0,
            radius: 5.0,
            spacing: 1.0,
            tries: 3000,
            seed: 3,
            band: 0.0,
        }
    }

    #[test]
    fn growing_is_deterministic_and_twins_pair_up() {
        let a = grow(&spec());
        assert_eq!(a, grow(&spec()));
        assert_ne!(a.discs, grow(&TileSpec { seed: 4, ..spec() }).discs);
        assert_eq!(a.tries, 3000);
        for (i, d) in a.discs.iter().enumerate() {
            if let Some(t) = d.twin {
                assert_eq!(a.discs[t].twin, Some(i));
                assert!(((a.discs[t].c[0] - d.c[0]).abs() - 50.0).abs() < 1e-12);
            }
        }
    }
}
