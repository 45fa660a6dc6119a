//! Reading a region from an SVG file (`--region svg:FILE`): every closed subpath of every
//! path, in document order, flattened to a polygon, in mm, in the region frame (y up).
//!
//! The file is parsed by usvg, which resolves transforms, units and shapes (rect, circle,
//! ellipse, polygon are paths to it). Coordinates come out in CSS pixels (96 per inch) and
//! are converted to mm (25.4 / 96 mm per px), with y flipped about the document's height.
//! Coordinates are rounded to 1e-4 mm (usvg computes in f32). Curves are flattened so that no chord is longer than 0.5 mm, with at least 8 pieces per
//! curve. Rings inside other rings are holes (the even-odd rule). Subpaths that are not
//! closed are ignored; a file with none is an error.
//!
//! The work is bounded whatever the file holds: a compressed file (SVGZ) is expanded to at
//! most the size of an uncompressed one; a number beyond [`MAX_NUMBER`] in path data, radii
//! or styles is refused before usvg sees it (usvg turns an arc into a number of curves
//! that grows with its radius, without end near the largest numbers); and the outline stops
//! at [`MAX_VERTICES`] vertices in [`MAX_RINGS`] rings (the core checks an outline through a
//! tree of its edges, in a time that grows as E log E: well under a second at the limits).

use std::path::Path;
use zetafill::Point;

const MM_PER_PX: f64 = 25.4 / 96.0;
const MAX_CHORD_MM: f64 = 0.5;

/// Largest number (in absolute value) in a file's path data (`d`), radii (`r`, `rx`, `ry`)
/// and styles: a billion user units, a thousand kilometres at 1 mm per unit.
pub const MAX_NUMBER: f64 = 1e9;

/// Farthest an outline's vertex may lie from the origin on either axis, in mm once its
/// transforms are applied (a kilometre, as for `--region polygon:`).
pub const MAX_COORDINATE_MM: f64 = 1_000_000.0;

/// Most vertices of an outline, its curves flattened.
pub const MAX_VERTICES: usize = 250_000;

/// Most rings (closed subpaths) of an outline.
pub const MAX_RINGS: usize = 25_000;

/// Why a file holds no outline. The caller says which flag named the file.
#[derive(Debug)]
pub enum OutlineError {
    /// The file cannot be read.
    Read(std::io::Error),
    /// The file is not SVG that usvg can parse.
    Svg(usvg::Error),
    /// The file has no closed path.
    NoClosedPath,
    /// The file has no filled path outside its decorations (a motif).
    NoFilledPath,
    /// A number of the geometry (as written, shortened) is beyond [`MAX_NUMBER`].
    Number(String),
    /// A vertex lies beyond [`MAX_COORDINATE_MM`] (or is not finite) once transformed: the
    /// coordinate, in mm.
    Far(f64),
    /// The outline has more than [`MAX_VERTICES`] vertices.
    TooManyVertices,
    /// The outline has more than [`MAX_RINGS`] rings.
    TooManyRings,
}

/// Rings of the outline: vertices, ring after ring, and the exclusive end of each ring.
pub fn read_outline(path: &Path) -> Result<(Vec<Point<f64>>, Vec<usize>), OutlineError> {
    let data = crate::io::read::read_limited(path, crate::io::read::MAX_SVG_BYTES, "an SVG outline").map_err(OutlineError::Read)?;
    outline_of(data)
}

/// Rings of the outline of the bytes of an SVG file, as [`read_outline`] reads them (for a
/// caller that has the file's bytes but no file system, such as the browser page).
pub fn outline_of(mut data: Vec<u8>) -> Result<(Vec<Point<f64>>, Vec<usize>), OutlineError> {
    if data.starts_with(&[0x1f, 0x8b]) {
        data = gunzip(&data)?;
    }
    if let Ok(text) = std::str::from_utf8(&data) {
        check_numbers(text)?;
    }
    let tree = usvg::Tree::from_data(&data, &usvg::Options::default()).map_err(OutlineError::Svg)?;
    let height = f64::from(tree.size().height());
    let mut rings: Vec<Vec<Point<f64>>> = Vec::new();
    let mut left = MAX_VERTICES;
    collect(tree.root(), height, &mut rings, &mut left)?;
    rings.retain(|r| r.len() >= 3);
    if rings.len() > MAX_RINGS {
        return Err(OutlineError::TooManyRings);
    }
    if rings.is_empty() {
        return Err(OutlineError::NoClosedPath);
    }
    if let Some(p) = rings
        .iter()
        .flatten()
        .find(|p| !(p.x.abs() <= MAX_COORDINATE_MM && p.y.abs() <= MAX_COORDINATE_MM))
    {
        return Err(OutlineError::Far(if p.x.abs() <= MAX_COORDINATE_MM { p.y } else { p.x }));
    }
    let mut points = Vec::new();
    let mut ends = Vec::new();
    for r in rings {
        points.extend(r);
        ends.push(points.len());
    }
    Ok((points, ends))
}

/// A motif read from an SVG (`--shape svg:FILE`): the rings of its filled paths, filled by
/// the even-odd rule, and its decorations, in mm (y up).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MotifOutline {
    /// Vertices, ring after ring.
    pub points: Vec<Point<f64>>,
    /// The exclusive end of each ring.
    pub ends: Vec<usize>,
    /// The polylines drawn with the motif and never tested: the subpaths of every path in a
    /// decoration (see [`motif_of`]) and of every path with a stroke and no fill. A closed
    /// subpath ends where it began.
    pub decoration: Vec<Vec<Point<f64>>>,
}

/// The motif of the bytes of an SVG file, its curves flattened so that no chord strays more
/// than `tolerance` mm from the curve (in the drawing's own size).
///
/// Every path with a fill gives its subpaths as rings (an open subpath is filled as if
/// closed, as SVG fills it); a path filled by the nonzero rule keeps just the rings across
/// which it changes from filled to empty, so that its rings together are filled by the
/// even-odd rule as they were by their own. The rings of all filled paths together are then
/// the motif under the even-odd rule: a path drawn inside another is a hole in it. A path or
/// group whose `id` or Inkscape layer name (`inkscape:label`) begins with `decoration`
/// (in any case), and everything inside one, is decoration, as is a path with a stroke and
/// no fill: drawn with the motif, never tested.
pub fn motif_of(mut data: Vec<u8>, tolerance: f64) -> Result<MotifOutline, OutlineError> {
    if data.starts_with(&[0x1f, 0x8b]) {
        data = gunzip(&data)?;
    }
    let mut named = std::collections::HashSet::new();
    if let Ok(text) = std::str::from_utf8(&data) {
        check_numbers(text)?;
        named = decoration_ids(text);
    }
    let tree = usvg::Tree::from_data(&data, &usvg::Options::default()).map_err(OutlineError::Svg)?;
    let mut walk = MotifWalk {
        height: f64::from(tree.size().height()),
        tolerance,
        named,
        left: MAX_VERTICES,
        out: MotifOutline::default(),
        rings: 0,
    };
    walk.group(tree.root(), false)?;
    let out = walk.out;
    if out.ends.is_empty() {
        return Err(OutlineError::NoFilledPath);
    }
    if let Some(p) = out
        .points
        .iter()
        .chain(out.decoration.iter().flatten())
        .find(|p| !(p.x.abs() <= MAX_COORDINATE_MM && p.y.abs() <= MAX_COORDINATE_MM))
    {
        return Err(OutlineError::Far(if p.x.abs() <= MAX_COORDINATE_MM { p.y } else { p.x }));
    }
    Ok(out)
}

/// The ids of the elements named as decoration by their Inkscape layer name.
fn decoration_ids(text: &str) -> std::collections::HashSet<String> {
    const INKSCAPE: &str = "http://www.inkscape.org/namespaces/inkscape";
    let opt = usvg::roxmltree::ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    };
    let Ok(doc) = usvg::roxmltree::Document::parse_with_options(text, opt) else {
        return Default::default();
    };
    doc.descendants()
        .filter(|n| n.attribute((INKSCAPE, "label")).is_some_and(is_decoration))
        .filter_map(|n| n.attribute("id").map(str::to_string))
        .collect()
}

/// Whether a name marks a decoration.
fn is_decoration(name: &str) -> bool {
    name.get(..10).is_some_and(|p| p.eq_ignore_ascii_case("decoration"))
}

/// The walk of an SVG tree that gathers a motif.
struct MotifWalk {
    height: f64,
    tolerance: f64,
    named: std::collections::HashSet<String>,
    left: usize,
    out: MotifOutline,
    rings: usize,
}

impl MotifWalk {
    fn marked(&self, id: &str) -> bool {
        is_decoration(id) || self.named.contains(id)
    }

    fn group(&mut self, g: &usvg::Group, decoration: bool) -> Result<(), OutlineError> {
        let decoration = decoration || self.marked(g.id());
        for node in g.children() {
            match node {
                usvg::Node::Group(g) => self.group(g, decoration)?,
                usvg::Node::Path(p) => self.path(p, decoration || self.marked(p.id()))?,
                _ => {}
            }
        }
        Ok(())
    }

    fn path(&mut self, p: &usvg::Path, decoration: bool) -> Result<(), OutlineError> {
        let tolerance = self.tolerance;
        let pieces = |ctrl: &[Point<f64>]| pieces_within(ctrl, tolerance);
        let fill = p.fill().filter(|_| !decoration);
        if fill.is_none() && !decoration && p.stroke().is_none() {
            return Ok(());
        }
        let subs = subpaths(p, self.height, &pieces, &mut self.left)?;
        let Some(fill) = fill else {
            for sub in subs {
                let mut line = sub.points;
                if sub.closed && line.first() != line.last() {
                    if let Some(&first) = line.first() {
                        line.push(first);
                    }
                }
                line.dedup();
                if line.len() >= 2 {
                    self.out.decoration.push(line);
                }
            }
            return Ok(());
        };
        let mut rings: Vec<Vec<Point<f64>>> = subs.into_iter().map(|s| ring_of(s.points)).filter(|r| r.len() >= 3).collect();
        if fill.rule() == usvg::FillRule::NonZero && rings.len() > 1 {
            rings = even_odd_of_nonzero(rings);
        }
        self.rings += rings.len();
        if self.rings > MAX_RINGS {
            return Err(OutlineError::TooManyRings);
        }
        for r in rings {
            self.out.points.extend(r);
            self.out.ends.push(self.out.points.len());
        }
        Ok(())
    }
}

/// The rings of a path filled by the nonzero rule that bound its fill: those across which
/// the winding number goes from zero to not zero, tested at two points either side of the
/// middle of each ring's longest edge.
fn even_odd_of_nonzero(rings: Vec<Vec<Point<f64>>>) -> Vec<Vec<Point<f64>>> {
    let filled = |q: Point<f64>| winding(&rings, q) != 0;
    let keep: Vec<bool> = rings
        .iter()
        .map(|r| {
            let edges = r.iter().zip(r.iter().cycle().skip(1));
            let Some((a, b)) = edges.max_by(|(a, b), (c, d)| len2(**a, **b).total_cmp(&len2(**c, **d))) else {
                return true;
            };
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let m = Point::new((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
            // A step of a millionth of the edge across it: inside the ring's neighbourhood.
            let e = 1e-6;
            filled(Point::new(m.x - dy * e, m.y + dx * e)) != filled(Point::new(m.x + dy * e, m.y - dx * e))
        })
        .collect();
    rings.into_iter().zip(keep).filter_map(|(r, k)| k.then_some(r)).collect()
}

fn len2(a: Point<f64>, b: Point<f64>) -> f64 {
    (b.x - a.x).powi(2) + (b.y - a.y).powi(2)
}

/// The winding number of the rings about `q`.
fn winding(rings: &[Vec<Point<f64>>], q: Point<f64>) -> i32 {
    let mut w = 0;
    for r in rings {
        for (a, b) in r.iter().zip(r.iter().cycle().skip(1)) {
            let side = (b.x - a.x) * (q.y - a.y) - (q.x - a.x) * (b.y - a.y);
            if a.y <= q.y && b.y > q.y && side > 0.0 {
                w += 1;
            } else if a.y > q.y && b.y <= q.y && side < 0.0 {
                w -= 1;
            }
        }
    }
    w
}

/// Pieces for a curve with this control polygon (3 points a quadratic, 4 a cubic) so that
/// no chord strays more than `tolerance` from it: a uniform cut into n pieces strays at most
/// max|B''| / (8 n^2), and |B''| is at most 2 (quadratic) or 6 (cubic) times the largest
/// second difference of the control points. At least 1 piece, at most 4,096.
fn pieces_within(ctrl: &[Point<f64>], tolerance: f64) -> usize {
    let second = ctrl
        .windows(3)
        .map(|w| {
            let (dx, dy) = (w[0].x - 2.0 * w[1].x + w[2].x, w[0].y - 2.0 * w[1].y + w[2].y);
            (dx * dx + dy * dy).sqrt()
        })
        .fold(0.0, f64::max);
    let k = if ctrl.len() == 3 { 0.25 } else { 0.75 };
    let n = (k * second / tolerance).sqrt().ceil();
    if n.is_finite() {
        (n as usize).clamp(1, 4096)
    } else {
        4096
    }
}

/// An SVGZ file expanded, to at most [`crate::io::read::MAX_SVG_BYTES`].
fn gunzip(data: &[u8]) -> Result<Vec<u8>, OutlineError> {
    use std::io::Read;
    let limit = crate::io::read::MAX_SVG_BYTES;
    let mut out = Vec::new();
    flate2::read::GzDecoder::new(data)
        .take(limit + 1)
        .read_to_end(&mut out)
        .map_err(|_| OutlineError::Svg(usvg::Error::MalformedGZip))?;
    if out.len() as u64 > limit {
        return Err(OutlineError::Read(std::io::Error::other(format!(
            "it expands to more than {} MiB, the most an SVG outline may be",
            limit >> 20
        ))));
    }
    Ok(out)
}

/// Refuses a number beyond [`MAX_NUMBER`] in path data, radii and styles (text that is not
/// XML is left to usvg to refuse).
fn check_numbers(text: &str) -> Result<(), OutlineError> {
    let opt = usvg::roxmltree::ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    };
    let Ok(doc) = usvg::roxmltree::Document::parse_with_options(text, opt) else {
        return Ok(());
    };
    for node in doc.descendants() {
        for a in node.attributes() {
            if matches!(a.name(), "d" | "r" | "rx" | "ry" | "style") {
                too_large(a.value())?;
            }
        }
        if node.has_tag_name("style") {
            for t in node.children().filter_map(|c| c.text()) {
                too_large(t)?;
            }
        }
    }
    Ok(())
}

/// The first number of `text` beyond [`MAX_NUMBER`] (or not finite), as an error.
fn too_large(text: &str) -> Result<(), OutlineError> {
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let digit = |k: usize| b.get(k).is_some_and(u8::is_ascii_digit);
        if !(digit(i) || (b[i] == b'.' && digit(i + 1))) {
            i += 1;
            continue;
        }
        let start = i;
        while digit(i) || b.get(i) == Some(&b'.') {
            i += 1;
        }
        if matches!(b.get(i), Some(b'e' | b'E')) {
            let j = if matches!(b.get(i + 1), Some(b'+' | b'-')) { i + 2 } else { i + 1 };
            if digit(j) {
                i = j;
                while digit(i) {
                    i += 1;
                }
            }
        }
        let num = text.get(start..i).unwrap_or("");
        // A second '.' starts the next number ("1.5.5" is 1.5 and .5): parse the longest
        // prefix that reads.
        let value = (1..=num.len()).rev().find_map(|k| num.get(..k).and_then(|p| p.parse::<f64>().ok()));
        if value.is_some_and(|v| v.is_nan() || v.abs() > MAX_NUMBER) {
            let shown: String = num.chars().take(24).collect();
            return Err(OutlineError::Number(if shown.len() < num.len() {
                format!("{shown}...")
            } else {
                shown
            }));
        }
    }
    Ok(())
}

fn collect(group: &usvg::Group, height: f64, rings: &mut Vec<Vec<Point<f64>>>, left: &mut usize) -> Result<(), OutlineError> {
    for node in group.children() {
        match node {
            usvg::Node::Group(g) => collect(g, height, rings, left)?,
            usvg::Node::Path(p) => flatten(p, height, rings, left)?,
            _ => {}
        }
    }
    Ok(())
}

/// Takes `n` vertices from the budget `left`.
fn spend(left: &mut usize, n: usize) -> Result<(), OutlineError> {
    *left = left.checked_sub(n).ok_or(OutlineError::TooManyVertices)?;
    Ok(())
}

/// A subpath of a path, its curves flattened, in mm: its vertices and whether it is closed
/// (by a `Z`, or by ending where it began).
struct Subpath {
    points: Vec<Point<f64>>,
    closed: bool,
}

/// Every closed subpath of `p` as a ring (its repeated first vertex and repeated vertices
/// dropped).
fn flatten(p: &usvg::Path, height: f64, rings: &mut Vec<Vec<Point<f64>>>, left: &mut usize) -> Result<(), OutlineError> {
    for sub in subpaths(p, height, &pieces, left)? {
        if sub.closed {
            rings.push(ring_of(sub.points));
        }
    }
    Ok(())
}

/// A closed subpath's vertices as a ring: no repeated first vertex, no vertex twice in a row.
fn ring_of(mut r: Vec<Point<f64>>) -> Vec<Point<f64>> {
    if r.len() >= 2 && r.first() == r.last() {
        r.pop();
    }
    r.dedup();
    r
}

/// The subpaths of `p`, each curve cut into `pieces(control polygon)` chords.
fn subpaths(p: &usvg::Path, height: f64, pieces: &dyn Fn(&[Point<f64>]) -> usize, left: &mut usize) -> Result<Vec<Subpath>, OutlineError> {
    let ts = p.abs_transform();
    let map = |x: f32, y: f32| {
        let (x, y) = (f64::from(x), f64::from(y));
        let (sx, ky, kx, sy, tx, ty) = (
            f64::from(ts.sx),
            f64::from(ts.ky),
            f64::from(ts.kx),
            f64::from(ts.sy),
            f64::from(ts.tx),
            f64::from(ts.ty),
        );
        let (px, py) = (sx * x + kx * y + tx, ky * x + sy * y + ty);
        // usvg works in f32: round to 1e-4 mm (0.1 µm) so that "90" reads back as 90.
        let snap = |v: f64| (v * 1e4).round() / 1e4;
        Point::new(snap(px * MM_PER_PX), snap((height - py) * MM_PER_PX))
    };
    let mut out = Vec::new();
    let mut cur: Vec<Point<f64>> = Vec::new();
    let mut last = Point::new(0.0, 0.0);
    let end = |out: &mut Vec<Subpath>, cur: &mut Vec<Point<f64>>, closed: bool| {
        let points = std::mem::take(cur);
        let closed = closed || (points.len() >= 3 && points.first() == points.last());
        if !points.is_empty() {
            out.push(Subpath { points, closed });
        }
    };
    for seg in p.data().segments() {
        use usvg::tiny_skia_path::PathSegment as S;
        match seg {
            S::MoveTo(a) => {
                end(&mut out, &mut cur, false);
                spend(left, 1)?;
                last = map(a.x, a.y);
                cur.push(last);
            }
            S::LineTo(a) => {
                spend(left, 1)?;
                last = map(a.x, a.y);
                cur.push(last);
            }
            S::QuadTo(b, c) => {
                let (b, c) = (map(b.x, b.y), map(c.x, c.y));
                let n = pieces(&[last, b, c]);
                spend(left, n)?;
                for k in 1..=n {
                    let t = k as f64 / n as f64;
                    let u = 1.0 - t;
                    cur.push(Point::new(
                        u * u * last.x + 2.0 * u * t * b.x + t * t * c.x,
                        u * u * last.y + 2.0 * u * t * b.y + t * t * c.y,
                    ));
                }
                last = c;
            }
            S::CubicTo(b, c, d) => {
                let (b, c, d) = (map(b.x, b.y), map(c.x, c.y), map(d.x, d.y));
                let n = pieces(&[last, b, c, d]);
                spend(left, n)?;
                for k in 1..=n {
                    let t = k as f64 / n as f64;
                    let u = 1.0 - t;
                    let (w0, w1, w2, w3) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
                    cur.push(Point::new(
                        w0 * last.x + w1 * b.x + w2 * c.x + w3 * d.x,
                        w0 * last.y + w1 * b.y + w2 * c.y + w3 * d.y,
                    ));
                }
                last = d;
            }
            S::Close => {
                let start = cur.first().copied().unwrap_or(last);
                end(&mut out, &mut cur, true);
                last = start;
            }
        }
    }
    end(&mut out, &mut cur, false);
    Ok(out)
}

/// Pieces for a curve with this control polygon: chords of at most 0.5 mm, at least 8.
fn pieces(ctrl: &[Point<f64>]) -> usize {
    let len: f64 = ctrl
        .windows(2)
        .map(|w| ((w[1].x - w[0].x).powi(2) + (w[1].y - w[0].y).powi(2)).sqrt())
        .sum();
    ((len / MAX_CHORD_MM).ceil() as usize).clamp(8, 10_000)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outline(svg: &str) -> Result<usize, OutlineError> {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let p = dir.path().join("a.svg");
        std::fs::write(&p, svg).unwrap_or_else(|e| panic!("{e}"));
        read_outline(&p).map(|(points, _)| points.len())
    }

    fn doc(body: &str) -> String {
        format!("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" viewBox=\"0 0 100 100\">{body}</svg>")
    }

    /// Found by the fuzz targets (cli/tests/fuzz.rs): one arc of radius 1e60 in a 150-byte
    /// file made usvg build curves without end (9 GB in 20 s), and one of radius 1e20 gave
    /// millions of vertices.
    #[test]
    fn huge_radii_and_endless_curves_are_refused() {
        for big in [
            "M0,0 A1e60 1e60 0 0 1 1e60 0 L0,50 Z",
            "M0,0 A1e20 1e20 0 0 1 1e20 0 L0,50 Z",
            "M0,0 L1e999,0 L0,50 Z",
        ] {
            let e = outline(&doc(&format!("<path d=\"{big}\"/>")));
            assert!(matches!(e, Err(OutlineError::Number(_))), "{big}: {e:?}");
        }
        let e = outline(&doc("<circle cx=\"50\" cy=\"50\" r=\"3e38\"/>"));
        assert!(matches!(e, Err(OutlineError::Number(_))), "{e:?}");
        let e = outline(&doc("<ellipse cx=\"50\" cy=\"50\" style=\"rx: 1e30px\" ry=\"4\"/>"));
        assert!(matches!(e, Err(OutlineError::Number(_))), "{e:?}");
        // Within the limit, a large curve stops at the vertex budget.
        let curves: String = (0..30).map(|k| format!("M{k},0 C1e5,1e5 -1e5,1e5 {k},1 Z ")).collect();
        let e = outline(&doc(&format!("<path d=\"{curves}\"/>")));
        assert!(matches!(e, Err(OutlineError::TooManyVertices)), "{e:?}");
        // Rings are counted too.
        let many: String = (0..=MAX_RINGS).map(|k| format!("M{0},1 L{0}.5,1 L{0},2 Z ", k % 90)).collect();
        let e = outline(&doc(&format!("<path d=\"{many}\"/>")));
        assert!(matches!(e, Err(OutlineError::TooManyRings)), "{e:?}");
        // A transform can carry small numbers far: the outline is measured once transformed.
        let e = outline(&doc("<path d=\"M10,10 L90,10 L50,80 Z\" transform=\"matrix(1e30,0,0,1,0,0)\"/>"));
        assert!(matches!(e, Err(OutlineError::Far(_))), "{e:?}");
        let e = outline(&doc("<g transform=\"scale(20000)\"><path d=\"M10,10 L90,10 L50,80 Z\"/></g>"));
        assert!(matches!(e, Err(OutlineError::Far(_))), "{e:?}");
        // Ordinary numbers pass: exponents, signs, a number run into the next.
        assert_eq!(outline(&doc("<path d=\"M10,10 L9e1,1e1 L50-5e-1.5,80Z\"/>")).ok(), Some(4));
    }

    #[test]
    fn compressed_files_expand_to_the_limit() {
        use std::io::Write;
        let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        gz.write_all(doc("<rect x=\"10\" y=\"10\" width=\"50\" height=\"50\"/>").as_bytes())
            .unwrap_or_else(|e| panic!("{e}"));
        let small = gz.finish().unwrap_or_else(|e| panic!("{e}"));
        assert!(gunzip(&small).is_ok());
        let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        let zeros = vec![b' '; 1 << 20];
        for _ in 0..=(crate::io::read::MAX_SVG_BYTES >> 20) {
            gz.write_all(&zeros).unwrap_or_else(|e| panic!("{e}"));
        }
        let bomb = gz.finish().unwrap_or_else(|e| panic!("{e}"));
        assert!(matches!(gunzip(&bomb), Err(OutlineError::Read(_))));
    }
}
