//! Voronoi diagrams by brute force, for the cobblestone and territory checks: a site's cell
//! as the box cut by the half-plane of every other site, and segment sets compared one to one.

/// A point (mm).
pub type Pt = [f64; 2];

/// The label of a cell edge that lies on the box, not on a bisector.
pub const ON_BOX: usize = usize::MAX;

/// The Voronoi cell of site `i` among all `pts`, clipped to the box `(x0, y0, x1, y1)`, by
/// half-planes: its vertices in order, each with the label of the edge from it to the next
/// (the other site whose bisector it lies on, or [`ON_BOX`]).
pub fn voronoi_cell(i: usize, pts: &[Pt], bbox: (f64, f64, f64, f64)) -> Vec<(Pt, usize)> {
    let (x0, y0, x1, y1) = bbox;
    let mut poly: Vec<(Pt, usize)> = vec![([x0, y0], ON_BOX), ([x1, y0], ON_BOX), ([x1, y1], ON_BOX), ([x0, y1], ON_BOX)];
    let s = pts[i];
    for (j, &o) in pts.iter().enumerate() {
        if j == i {
            continue;
        }
        let n = [o[0] - s[0], o[1] - s[1]];
        let c = (o[0] * o[0] + o[1] * o[1] - s[0] * s[0] - s[1] * s[1]) / 2.0;
        let side = |p: Pt| n[0] * p[0] + n[1] * p[1] - c; // <= 0: nearer to s
        let mut out: Vec<(Pt, usize)> = Vec::new();
        for k in 0..poly.len() {
            let (a, la) = poly[k];
            let (b, _) = poly[(k + 1) % poly.len()];
            let (sa, sb) = (side(a), side(b));
            if sa <= 0.0 {
                out.push((a, la));
            }
            if (sa <= 0.0) != (sb <= 0.0) {
                let t = sa / (sa - sb);
                let p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                // Entering: the edge from p on keeps a's label; leaving: p starts the cut.
                if sa <= 0.0 {
                    out.push((p, j));
                } else {
                    out.push((p, la));
                }
            }
        }
        poly = out;
    }
    poly
}

/// The segments of polylines, each consecutive pair of points once.
pub fn segments(lines: &[Vec<Pt>]) -> Vec<(Pt, Pt)> {
    lines.iter().flat_map(|l| l.windows(2).map(|w| (w[0], w[1]))).collect()
}

/// Whether two segments are the same within `tol`, in either direction.
pub fn same_segment(a: &(Pt, Pt), b: &(Pt, Pt), tol: f64) -> bool {
    let close = |p: Pt, q: Pt| (p[0] - q[0]).abs() <= tol && (p[1] - q[1]).abs() <= tol;
    (close(a.0, b.0) && close(a.1, b.1)) || (close(a.0, b.1) && close(a.1, b.0))
}

/// Matches segments one to one (either direction) within `tol`. Returns the problems: one
/// per segment of `want` not found, one per segment of `got` left over.
pub fn segment_mismatch(got: &[(Pt, Pt)], want: &[(Pt, Pt)], tol: f64) -> Vec<String> {
    let mut used = vec![false; got.len()];
    let mut problems = Vec::new();
    for w in want {
        match (0..got.len()).find(|&g| !used[g] && same_segment(&got[g], w, tol)) {
            Some(g) => used[g] = true,
            None => problems.push(format!("missing {w:?}")),
        }
    }
    for (g, u) in used.iter().enumerate() {
        if !u {
            problems.push(format!("extra {:?}", got[g]));
        }
    }
    problems
}
