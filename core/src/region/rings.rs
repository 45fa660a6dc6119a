//! Edge lookup over the rings of a polygon region: edge `i` runs from vertex `i` to the next
//! vertex of its ring (the last vertex of a ring joins its first), found in a table of next
//! vertices when the edge tree holds one, else by a binary search of the ring ends. Ring ends
//! are assumed increasing (the region checks them first); lookups out of range give empty
//! answers, never a panic.

use crate::geom::Point;

/// The rings: `points` split at the exclusive indices `ends`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Rings<'a> {
    pub points: &'a [Point<f64>],
    pub ends: &'a [usize],
    /// The vertex after each vertex, or empty.
    pub next: &'a [u32],
}

impl<'a> Rings<'a> {
    /// The number of edges (one per vertex).
    #[inline]
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// The ring holding vertex `i`: its number, start and exclusive end (a binary search).
    #[inline]
    pub fn ring_of(&self, i: usize) -> (usize, usize, usize) {
        let r = self.ends.partition_point(|&e| e <= i);
        let start = match r.checked_sub(1) {
            Some(q) => self.ends.get(q).copied().unwrap_or(0),
            None => 0,
        };
        (r, start, self.ends.get(r).copied().unwrap_or(start))
    }

    /// Start and exclusive end of ring `r`.
    #[inline]
    pub fn ring(&self, r: usize) -> (usize, usize) {
        let start = match r.checked_sub(1) {
            Some(q) => self.ends.get(q).copied().unwrap_or(0),
            None => 0,
        };
        (start, self.ends.get(r).copied().unwrap_or(start))
    }

    /// The vertex after `i` in its ring.
    #[inline]
    pub fn next(&self, i: usize) -> usize {
        if let Some(&j) = self.next.get(i) {
            return j as usize;
        }
        let (_, s, e) = self.ring_of(i);
        if i + 1 >= e {
            s
        } else {
            i + 1
        }
    }

    /// The edge starting at vertex `i`.
    #[inline]
    pub fn edge(&self, i: usize) -> (Point<f64>, Point<f64>) {
        let a = self.points.get(i).copied().unwrap_or_default();
        let b = self.points.get(self.next(i)).copied().unwrap_or_default();
        (a, b)
    }

    /// The bounding box (min x, min y, max x, max y) of edge `i`.
    #[inline]
    pub fn bbox(&self, i: usize) -> (f64, f64, f64, f64) {
        let (a, b) = self.edge(i);
        (a.x.min(b.x), a.y.min(b.y), a.x.max(b.x), a.y.max(b.y))
    }

    /// Writes the vertex after each vertex into `table` (which must hold `len()` words).
    pub fn fill_next(&self, table: &mut [u32]) {
        let mut start = 0usize;
        for &e in self.ends {
            for i in start..e {
                if let Some(t) = table.get_mut(i) {
                    *t = if i + 1 >= e { start as u32 } else { i as u32 + 1 };
                }
            }
            start = e;
        }
    }

    /// Ring `r`'s vertices.
    pub fn slice(&self, r: usize) -> &'a [Point<f64>] {
        let (s, e) = self.ring(r);
        self.points.get(s..e).unwrap_or(&[])
    }
}
