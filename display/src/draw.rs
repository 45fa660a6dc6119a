//! Drawing placed shapes onto a display.
//!
//! A [`View`] maps the region's frame (mm, x right, y up, origin at the lower-left corner)
//! onto pixels (x right, y down): one scale `k` for both axes, the largest that fits the
//! region's bounding box into the display, its lower-left corner at the bottom-left pixel.
//!
//! - [`View::draw`] draws a shape as an outline one pixel wide on a monochrome display: a
//!   circle with `embedded-graphics`' circle, a ring as its two circles, a polygon as the lines
//!   between its vertices, exactly the [`Geo`] the engine tested.
//! - [`View::fill`] fills a shape in any colour type (`BinaryColor` for an OLED, `Rgb565` for
//!   a TFT, ...): every pixel whose centre lies inside the shape takes the colour, and no
//!   other. Rows are filled in spans, from the crossings of each pixel row's centre line with
//!   the shape's outline (even-odd for polygons, so stars and blobs come out whole; a ring
//!   leaves its hole).
//!
//! In a periodic region every image of a shape that crosses an edge is drawn too, so the
//! picture tiles (a fill shows one period: the pixels whose centres lie in the region's box). Pixel coordinates are computed in `f64` with basic IEEE operations, libm's
//! correctly rounded square root and truncating casts only: the same on every target, for
//! every scalar.

use embedded_graphics::framebuffer::{buffer_size, Framebuffer};
use embedded_graphics::geometry::Point as Px;
use embedded_graphics::pixelcolor::raw::{BigEndian, RawU1};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Line, PrimitiveStyle, Rectangle};
use zetafill::internals::geom::MAX_VERTS;
use zetafill::{Geo, Region, Scalar};

/// Display width in pixels.
pub const WIDTH: usize = 128;
/// Display height in pixels.
pub const HEIGHT: usize = 64;

/// The 128x64 monochrome framebuffer of an SSD1306 OLED: rows top to bottom, 16 bytes a row, the leftmost pixel
/// in the most significant bit, 1 = ink. These bytes are the data of a binary PBM (`P4`) image.
pub type Frame = Framebuffer<BinaryColor, RawU1, BigEndian, WIDTH, HEIGHT, FRAME_BYTES>;

/// Bytes in a [`Frame`].
pub const FRAME_BYTES: usize = buffer_size::<BinaryColor>(WIDTH, HEIGHT);

/// The header that makes a [`Frame`]'s bytes a binary PBM file.
pub const PBM_HEADER: &[u8] = b"P4\n128 64\n";

/// Largest integer not above `v`, saturated to `i32` (NaN gives 0).
fn floor_i32(v: f64) -> i32 {
    let t = v as i32;
    if (t as f64) > v {
        t.saturating_sub(1)
    } else {
        t
    }
}

/// Smallest integer not below `v`, saturated to `i32` (NaN gives 0).
fn ceil_i32(v: f64) -> i32 {
    floor_i32(-v).saturating_neg()
}

/// How a region maps onto a display.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    k: f64,
    x0: f64,
    y0: f64,
    w: f64,
    h: f64,
    bottom: f64,
    periodic: bool,
}

impl View {
    /// The view of `region` on a display of `width` x `height` pixels.
    pub fn new(region: &Region<'_>, width: u32, height: u32) -> View {
        let (x0, y0, _, _) = region.bbox();
        let (w, h) = region.extent();
        let (pw, ph) = (f64::from(width.saturating_sub(1)), f64::from(height.saturating_sub(1)));
        let (kx, ky) = (pw / w, ph / h);
        let k = if kx < ky { kx } else { ky };
        let k = if k.is_finite() && k > 0.0 { k } else { 0.0 };
        View {
            k,
            x0,
            y0,
            w,
            h,
            bottom: ph,
            periodic: region.periodic(),
        }
    }

    /// Pixels per mm.
    pub fn scale(&self) -> f64 {
        self.k
    }

    /// The pixel of the point (x, y) in mm.
    pub fn pixel(&self, x: f64, y: f64) -> Px {
        Px::new(floor_i32((x - self.x0) * self.k), floor_i32(self.bottom - (y - self.y0) * self.k))
    }

    /// Draws a shape's outline (and, in a periodic region, its images across the edges).
    pub fn draw<S: Scalar, D: DrawTarget<Color = BinaryColor>>(&self, geo: &Geo<S>, target: &mut D) -> Result<(), D::Error> {
        self.each_image(geo, |dx, dy| self.draw_at(geo, dx, dy, target))
    }

    /// Fills a shape with `colour` (and, in a periodic region, its images across the edges):
    /// exactly the pixels whose centres lie inside it.
    pub fn fill<S: Scalar, C: PixelColor, D: DrawTarget<Color = C>>(
        &self,
        geo: &Geo<S>,
        colour: C,
        target: &mut D,
    ) -> Result<(), D::Error> {
        self.each_image(geo, |dx, dy| self.fill_at(geo, dx, dy, colour, target))
    }

    /// Calls `f` with the shift of the shape and of each of its periodic images that reaches
    /// the region's bounding box.
    fn each_image<S: Scalar, E>(&self, geo: &Geo<S>, mut f: impl FnMut(f64, f64) -> Result<(), E>) -> Result<(), E> {
        let (x0, y0, x1, y1) = geo.bounds();
        let (x0, y0, x1, y1) = (x0.to_f64(), y0.to_f64(), x1.to_f64(), y1.to_f64());
        let shifts: &[f64] = if self.periodic { &[0.0, -1.0, 1.0] } else { &[0.0] };
        for &sy in shifts {
            for &sx in shifts {
                let (dx, dy) = (sx * self.w, sy * self.h);
                // Skip images that lie entirely outside the region's bounding box.
                let (bx0, by0) = (self.x0, self.y0);
                if x1 + dx < bx0 || x0 + dx > bx0 + self.w || y1 + dy < by0 || y0 + dy > by0 + self.h {
                    continue;
                }
                f(dx, dy)?;
            }
        }
        Ok(())
    }

    /// The point (x, y) in mm in pixel units: pixel (i, j) covers `[i, i + 1) x [j, j + 1)`,
    /// its centre at (i + 1/2, j + 1/2).
    fn px_of(&self, x: f64, y: f64) -> (f64, f64) {
        ((x - self.x0) * self.k, self.bottom - (y - self.y0) * self.k)
    }

    fn fill_at<S: Scalar, C: PixelColor, D: DrawTarget<Color = C>>(
        &self,
        geo: &Geo<S>,
        dx: f64,
        dy: f64,
        colour: C,
        target: &mut D,
    ) -> Result<(), D::Error> {
        let mut area = target.bounding_box();
        if self.periodic {
            // A torus shows one period: the pixels whose centres lie in the region's box.
            let (i0, j0) = (0, ceil_i32(self.bottom - self.h * self.k - 0.5));
            let (i1, j1) = (floor_i32(self.w * self.k - 0.5), floor_i32(self.bottom - 0.5));
            let size = Size::new(
                i1.saturating_sub(i0).saturating_add(1).max(0) as u32,
                j1.saturating_sub(j0).saturating_add(1).max(0) as u32,
            );
            area = area.intersection(&Rectangle::new(Px::new(i0, j0), size));
        }
        let (x0, y0, x1, y1) = geo.bounds();
        let (px0, py1) = self.px_of(x0.to_f64() + dx, y0.to_f64() + dy);
        let (px1, py0) = self.px_of(x1.to_f64() + dx, y1.to_f64() + dy);
        // Rows whose centre line can meet the shape, within the display.
        let top = area.top_left.y;
        let bottom = top.saturating_add(area.size.height as i32);
        let first = ceil_i32(py0 - 0.5).max(top);
        let last = floor_i32(py1 - 0.5).min(bottom.saturating_sub(1));
        if px1 < f64::from(area.top_left.x) || px0 > f64::from(area.top_left.x.saturating_add(area.size.width as i32)) {
            return Ok(());
        }
        let mut row = first;
        while row <= last {
            let yc = f64::from(row) + 0.5;
            let mut xs = [0.0f64; MAX_VERTS + 2];
            let n = self.crossings(geo, dx, dy, yc, &mut xs);
            let xs = xs.get(..n).unwrap_or(&[]);
            for pair in xs.chunks_exact(2) {
                if let [a, b] = *pair {
                    // Pixels whose centre i + 1/2 lies in [a, b).
                    let (i0, i1) = (ceil_i32(a - 0.5), ceil_i32(b - 0.5).saturating_sub(1));
                    if i1 >= i0 {
                        let span = Rectangle::new(Px::new(i0, row), Size::new(i1.saturating_sub(i0).saturating_add(1) as u32, 1));
                        target.fill_solid(&span.intersection(&area), colour)?;
                    }
                }
            }
            row = row.saturating_add(1);
        }
        Ok(())
    }

    /// The x (pixel units) where the row line y = `yc` crosses the shape's outline, sorted
    /// into `xs`; their count (even: inside between each pair).
    fn crossings<S: Scalar>(&self, geo: &Geo<S>, dx: f64, dy: f64, yc: f64, xs: &mut [f64; MAX_VERTS + 2]) -> usize {
        let mut n = 0;
        let mut push = |x: f64, n: &mut usize| {
            if let Some(slot) = xs.get_mut(*n) {
                *slot = x;
                *n += 1;
            }
        };
        // Half the chord of a circle of radius r (px) at height h from its centre.
        let chord = |r: f64, h: f64| {
            let q = r * r - h * h;
            if q > 0.0 {
                Some(zetafill::internals::scalar::sqrtf(q))
            } else {
                None
            }
        };
        match *geo {
            Geo::Circle { c, r } | Geo::Ring { c, r, .. } => {
                let (cx, cy) = self.px_of(c.x.to_f64() + dx, c.y.to_f64() + dy);
                let h = yc - cy;
                if let Some(half) = chord(r.to_f64() * self.k, h) {
                    push(cx - half, &mut n);
                    if let Geo::Ring { inner, .. } = *geo {
                        if let Some(hole) = chord(inner.to_f64() * self.k, h) {
                            push(cx - hole, &mut n);
                            push(cx + hole, &mut n);
                        }
                    }
                    push(cx + half, &mut n);
                }
            }
            Geo::Poly { .. } | Geo::Motif { .. } => {
                let mut edge = |a: zetafill::Point<S>, b: zetafill::Point<S>, n: &mut usize| {
                    let (ax, ay) = self.px_of(a.x.to_f64() + dx, a.y.to_f64() + dy);
                    let (bx, by) = self.px_of(b.x.to_f64() + dx, b.y.to_f64() + dy);
                    // Half-open in y, so a vertex on the line counts once.
                    if (ay <= yc) != (by <= yc) {
                        push(ax + (yc - ay) * (bx - ax) / (by - ay), n);
                    }
                };
                if let Geo::Motif { m, ref f } = *geo {
                    for ring in m.rings_at(f) {
                        let mut ring = ring.peekable();
                        let first = ring.peek().copied();
                        let mut prev = None;
                        for p in ring.chain(first) {
                            if let Some(a) = prev {
                                edge(a, p, &mut n);
                            }
                            prev = Some(p);
                        }
                    }
                }
                let vs = geo.vertices();
                let m = vs.len();
                for i in 0..m {
                    if let (Some(&a), Some(&b)) = (vs.get(i), vs.get((i + 1) % m)) {
                        edge(a, b, &mut n);
                    }
                }
                // Insertion sort: at most MAX_VERTS crossings.
                let mut i = 1;
                while i < n {
                    let mut j = i;
                    while j > 0 {
                        match (xs.get(j - 1).copied(), xs.get(j).copied()) {
                            (Some(p), Some(q)) if p > q => xs.swap(j - 1, j),
                            _ => break,
                        }
                        j -= 1;
                    }
                    i += 1;
                }
            }
        }
        n
    }

    fn draw_at<S: Scalar, D: DrawTarget<Color = BinaryColor>>(
        &self,
        geo: &Geo<S>,
        dx: f64,
        dy: f64,
        target: &mut D,
    ) -> Result<(), D::Error> {
        let style = PrimitiveStyle::with_stroke(BinaryColor::On, 1);
        let circle = |c: zetafill::Point<S>, r: S| {
            let centre = self.pixel(c.x.to_f64() + dx, c.y.to_f64() + dy);
            let d = floor_i32(2.0 * r.to_f64() * self.k + 0.5).max(1);
            Circle::with_center(centre, d as u32).into_styled(style)
        };
        match *geo {
            Geo::Circle { c, r } => circle(c, r).draw(target),
            Geo::Ring { c, r, inner } => {
                circle(c, r).draw(target)?;
                circle(c, inner).draw(target)
            }
            Geo::Poly { .. } => {
                let vs = geo.vertices();
                let px = |i: usize| {
                    i.checked_rem(vs.len())
                        .and_then(|j| vs.get(j))
                        .map(|p| self.pixel(p.x.to_f64() + dx, p.y.to_f64() + dy))
                };
                for i in 0..vs.len() {
                    if let (Some(a), Some(b)) = (px(i), px(i + 1)) {
                        Line::new(a, b).into_styled(style).draw(target)?;
                    }
                }
                Ok(())
            }
            Geo::Motif { m, ref f } => {
                for ring in m.rings_at(f) {
                    let mut ring = ring.map(|p| self.pixel(p.x.to_f64() + dx, p.y.to_f64() + dy)).peekable();
                    let first = ring.peek().copied();
                    let mut prev = None;
                    for p in ring.chain(first) {
                        if let Some(a) = prev {
                            Line::new(a, p).into_styled(style).draw(target)?;
                        }
                        prev = Some(p);
                    }
                }
                Ok(())
            }
        }
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::indexing_slicing)]
mod tests {
    use super::*;
    use embedded_graphics::image::GetPixel;
    use zetafill::Point;

    fn ink(f: &Frame) -> usize {
        f.data().iter().map(|b| b.count_ones() as usize).sum()
    }

    #[test]
    fn region_corners_map_to_display_corners() {
        let v = View::new(
            &Region::Rect {
                width: 200.0,
                height: 100.0,
                periodic: false,
            },
            128,
            128,
        );
        assert_eq!(v.pixel(0.0, 0.0), Px::new(0, 127));
        assert_eq!(v.pixel(200.0, 0.0), Px::new(127, 127));
        // 127 - 100 * 0.635 = 63.5, floored.
        assert_eq!(v.pixel(0.0, 100.0).y, 63);
    }

    #[test]
    fn a_square_is_drawn_as_its_outline_and_a_circle_round() {
        let view = View::new(
            &Region::Rect {
                width: 127.0,
                height: 63.0,
                periodic: false,
            },
            128,
            64,
        );
        let mut f = Frame::new();
        let p = |x, y| Point::new(x, y);
        let v = [p(10.0, 10.0), p(20.0, 10.0), p(20.0, 20.0), p(10.0, 20.0)].into_iter().collect();
        let sq = Geo::Poly { v, convex: true };
        view.draw(&sq, &mut f).unwrap();
        assert_eq!(ink(&f), 40);
        assert_eq!(f.pixel(Px::new(10, 53)), Some(BinaryColor::On));
        assert_eq!(f.pixel(Px::new(15, 48)), Some(BinaryColor::Off));
        let mut g = Frame::new();
        view.draw(&Geo::Circle { c: p(64.0, 32.0), r: 10.0 }, &mut g).unwrap();
        assert_eq!(g.pixel(Px::new(64, 31)), Some(BinaryColor::Off));
        assert!(ink(&g) > 50);
        let mut r = Frame::new();
        view.draw(
            &Geo::Ring {
                c: p(64.0, 32.0),
                r: 10.0,
                inner: 5.0,
            },
            &mut r,
        )
        .unwrap();
        assert!(ink(&r) > ink(&g));
    }

    #[test]
    fn periodic_regions_draw_the_images_across_edges() {
        let p = |x, y| Point::new(x, y);
        let c = Geo::Circle { c: p(1.0, 32.0), r: 5.0 };
        let mut inc = Frame::new();
        View::new(
            &Region::Rect {
                width: 127.0,
                height: 63.0,
                periodic: false,
            },
            128,
            64,
        )
        .draw(&c, &mut inc)
        .unwrap();
        let mut per = Frame::new();
        View::new(
            &Region::Rect {
                width: 127.0,
                height: 63.0,
                periodic: true,
            },
            128,
            64,
        )
        .draw(&c, &mut per)
        .unwrap();
        assert!(ink(&per) > ink(&inc));
        let right_edge = |f: &Frame| (120..128).any(|x| (0..64).any(|y| f.pixel(Px::new(x, y)) == Some(BinaryColor::On)));
        assert!(right_edge(&per) && !right_edge(&inc));
    }
}
