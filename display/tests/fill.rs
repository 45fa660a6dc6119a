//! `View::fill` paints exactly the pixels whose centres lie inside a shape: fills of the
//! firmware's scenes (circles, rotated squares on a torus, hexagons in a disc, stars in an
//! annulus, rings, blobs, a mix in a room with a hole) on a 160 x 128 `Rgb565` display (an
//! ST7735 TFT's) and on the 128 x 64 monochrome frame, compared pixel by pixel with an
//! independent judgement of each pixel centre against every placed shape and its periodic
//! images. The comparison is shown to fail on a shape moved by one pixel and on a wrong
//! colour. A property test fills wild shapes (not a number, huge, inside out) without a
//! panic.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

use embedded_graphics::framebuffer::{buffer_size, Framebuffer};
use embedded_graphics::geometry::Point as Px;
use embedded_graphics::image::GetPixel;
use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};
use embedded_graphics::pixelcolor::{BinaryColor, Rgb565};
use embedded_graphics::prelude::*;
use zetafill::{Engine, Geo, Placed, Region, Storage};
use zetafill_display::scenes::{Scene, CAPACITY, INDEX_WORDS, SCENES};
use zetafill_display::{Frame, View};

const TFT_W: usize = 160;
const TFT_H: usize = 128;
type Tft = Framebuffer<Rgb565, RawU16, LittleEndian, TFT_W, TFT_H, { buffer_size::<Rgb565>(TFT_W, TFT_H) }>;

const PALETTE: [Rgb565; 5] = [Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE, Rgb565::YELLOW, Rgb565::CYAN];

/// A scene's shapes, placed on the host in f64, and its region.
fn placed(scene: &Scene) -> (Region<'static>, Vec<Geo<'static, f64>>) {
    let region = scene.region.region().unwrap_or_else(|e| panic!("{}: {e}", scene.name));
    let params = scene.params().unwrap_or_else(|e| panic!("{}: {e}", scene.name));
    let mut shapes = vec![Placed::<f64>::default(); CAPACITY];
    let mut index = vec![0u32; INDEX_WORDS];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let mut e = Engine::<f64>::new(params, region, storage).unwrap_or_else(|e| panic!("{}: {e}", scene.name));
    let mut rng = zetafill::rng_from_seed(scene.seed);
    while (e.placed().len() as u64) < scene.count {
        e.step(&mut rng).unwrap_or_else(|err| panic!("{}: {err}", scene.name));
    }
    let geos = (0..e.placed().len()).filter_map(|i| e.geo(i).and_then(|g| g.owned())).collect();
    (region, geos)
}

/// Whether `p` is inside `g`, and how far it is from the outline (mm).
fn judge(g: &Geo<f64>, p: [f64; 2]) -> (bool, f64) {
    match *g {
        Geo::Circle { c, r } => {
            let d = (p[0] - c.x).hypot(p[1] - c.y);
            (d < r, (d - r).abs())
        }
        Geo::Ring { c, r, inner } => {
            let d = (p[0] - c.x).hypot(p[1] - c.y);
            (d < r && d > inner, (d - r).abs().min((d - inner).abs()))
        }
        Geo::Poly { .. } => {
            let vs = g.vertices();
            let mut inside = false;
            let mut near = f64::INFINITY;
            for i in 0..vs.len() {
                let (a, b) = (vs[i], vs[(i + 1) % vs.len()]);
                if (a.y > p[1]) != (b.y > p[1]) && p[0] < a.x + (p[1] - a.y) * (b.x - a.x) / (b.y - a.y) {
                    inside = !inside;
                }
                // Distance to the edge ab.
                let (ex, ey) = (b.x - a.x, b.y - a.y);
                let t = (((p[0] - a.x) * ex + (p[1] - a.y) * ey) / (ex * ex + ey * ey)).clamp(0.0, 1.0);
                near = near.min((p[0] - a.x - t * ex).hypot(p[1] - a.y - t * ey));
            }
            (inside, near)
        }
        Geo::Motif { .. } => unreachable!("the scenes have no motifs"),
    }
}

/// Pixels of a `width` x `height` display whose colour index (`got`, `None` for the
/// background) is not that of the shape holding the pixel's centre, under the README's
/// mapping of the region onto the display, each shape moved by `nudge` (mm). Pixels whose
/// centre is within a millionth of a pixel of an outline are not judged.
fn faults(
    region: &Region<'_>,
    geos: &[Geo<f64>],
    (width, height): (u32, u32),
    nudge: [f64; 2],
    colour_of: impl Fn(usize) -> usize,
    got: impl Fn(i32, i32) -> Option<usize>,
) -> Vec<String> {
    let (x0, y0, _, _) = region.bbox();
    let (w, h) = region.extent();
    let k = (f64::from(width - 1) / w).min(f64::from(height - 1) / h);
    let bottom = f64::from(height - 1);
    let shifts: Vec<(f64, f64)> = if region.periodic() {
        [-1.0, 0.0, 1.0]
            .iter()
            .flat_map(|&sx| [-1.0, 0.0, 1.0].map(|sy| (sx * w, sy * h)))
            .collect()
    } else {
        vec![(0.0, 0.0)]
    };
    let mut bad = Vec::new();
    for j in 0..height as i32 {
        for i in 0..width as i32 {
            let p = [x0 + (f64::from(i) + 0.5) / k, y0 + (bottom - f64::from(j) - 0.5) / k];
            let mut want = None;
            let mut unsure = false;
            // A torus shows one period.
            let in_box = p[0] >= x0 && p[0] <= x0 + w && p[1] >= y0 && p[1] <= y0 + h;
            for (n, g) in geos.iter().enumerate().filter(|_| in_box || !region.periodic()) {
                let (bx0, by0, bx1, by1) = g.bounds();
                for &(dx, dy) in &shifts {
                    let q = [p[0] - dx - nudge[0], p[1] - dy - nudge[1]];
                    if q[0] < bx0 - 1.0 || q[0] > bx1 + 1.0 || q[1] < by0 - 1.0 || q[1] > by1 + 1.0 {
                        continue;
                    }
                    let (inside, near) = judge(g, q);
                    unsure |= near * k < 1e-6;
                    if inside {
                        want = Some(colour_of(n));
                    }
                }
            }
            if !unsure && got(i, j) != want {
                bad.push(format!("pixel ({i}, {j}): {:?}, expected {want:?}", got(i, j)));
            }
        }
    }
    bad
}

const NAMES: [&str; 7] = [
    "circles-torus",
    "squares",
    "hexagons-disc",
    "stars-annulus",
    "rings-fixed",
    "blobs",
    "mix-room",
];

fn scene(name: &str) -> &'static Scene {
    SCENES.iter().find(|s| s.name == name).unwrap_or_else(|| panic!("no scene {name}"))
}

#[test]
fn a_colour_display_shows_exactly_the_shapes() {
    for name in NAMES {
        let (region, geos) = placed(scene(name));
        let mut tft = Tft::new();
        let view = View::new(&region, TFT_W as u32, TFT_H as u32);
        for (n, g) in geos.iter().enumerate() {
            view.fill(g, PALETTE[n % PALETTE.len()], &mut tft).unwrap_or_else(|e| match e {});
        }
        let got = |i: i32, j: i32| {
            let c = tft
                .pixel(Px::new(i, j))
                .unwrap_or_else(|| panic!("pixel ({i}, {j}) off the display"));
            (c != Rgb565::BLACK).then(|| PALETTE.iter().position(|&q| q == c).unwrap_or(usize::MAX))
        };
        let size = (TFT_W as u32, TFT_H as u32);
        let colour_of = |n: usize| n % PALETTE.len();
        let bad = faults(&region, &geos, size, [0.0, 0.0], colour_of, got);
        assert!(bad.is_empty(), "{name}: {} pixels wrong, first {:?}", bad.len(), bad.first());
        let inked = (0..TFT_H as i32)
            .flat_map(|j| (0..TFT_W as i32).map(move |i| (i, j)))
            .filter(|&(i, j)| got(i, j).is_some())
            .count();
        assert!(inked > 1000, "{name}: {inked} pixels painted");
        // The check can fail: the shapes moved by a pixel, or painted in the wrong colours.
        let pixel = 1.0 / view.scale();
        assert!(
            !faults(&region, &geos, size, [pixel, 0.0], colour_of, got).is_empty(),
            "{name}: a shift is missed"
        );
        let wrong = |i: i32, j: i32| got(i, j).map(|c| (c + 1) % PALETTE.len());
        assert!(
            !faults(&region, &geos, size, [0.0, 0.0], colour_of, wrong).is_empty(),
            "{name}: a wrong colour is missed"
        );
    }
}

#[test]
fn the_monochrome_frame_is_filled_the_same_way() {
    for name in NAMES {
        let (region, geos) = placed(scene(name));
        let mut frame = Frame::new();
        let view = View::new(&region, 128, 64);
        for g in &geos {
            view.fill(g, BinaryColor::On, &mut frame).unwrap_or_else(|e| match e {});
        }
        let on = |i: i32, j: i32| (frame.pixel(Px::new(i, j)) == Some(BinaryColor::On)).then_some(0);
        let bad = faults(&region, &geos, (128, 64), [0.0, 0.0], |_| 0, on);
        assert!(bad.is_empty(), "{name}: {} pixels wrong, first {:?}", bad.len(), bad.first());
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig {
        cases: 256,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0xf111),
        ..proptest::prelude::ProptestConfig::default()
    })]

    /// Any shape, however wild (huge, inside out, not a number, off the display), is filled
    /// without a panic, on a colour and a monochrome display, in a rectangle and on a torus.
    #[test]
    fn any_shape_fills_without_a_panic(
        kind in 0u8..3,
        c in proptest::array::uniform2(proptest::prop_oneof![proptest::num::f64::ANY, -1e3f64..1e3]),
        r in proptest::prop_oneof![proptest::num::f64::ANY, 0.0f64..500.0],
        inner in proptest::prop_oneof![proptest::num::f64::ANY, 0.0f64..500.0],
        vs in proptest::collection::vec(proptest::array::uniform2(proptest::prop_oneof![proptest::num::f64::ANY, -1e4f64..1e4]), 3..=32),
        periodic in proptest::bool::ANY,
    ) {
        use zetafill::Point;
        let p = |q: [f64; 2]| Point::new(q[0], q[1]);
        let g = match kind {
            0 => Geo::Circle { c: p(c), r },
            1 => Geo::Ring { c: p(c), r, inner },
            _ => {
                let v = vs.iter().map(|q| p(*q)).collect();
                Geo::Poly { v, convex: false }
            }
        };
        let region = Region::Rect { width: 120.0, height: 80.0, periodic };
        let mut tft = Tft::new();
        View::new(&region, TFT_W as u32, TFT_H as u32).fill(&g, Rgb565::WHITE, &mut tft).unwrap_or_else(|e| match e {});
        let mut frame = Frame::new();
        View::new(&region, 128, 64).fill(&g, BinaryColor::On, &mut frame).unwrap_or_else(|e| match e {});
    }
}
