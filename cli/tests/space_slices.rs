//! Slices for stacked laser cuts checked against the exact cross-sections: every outline point
//! lies on the solid's surface in the cutting plane, and a grid of points of the plane is
//! inside the drawn outline (even-odd) exactly when it is inside the solid. The checker has
//! twins fed broken sections that must fail. The sheets are written as SVG (read back by
//! usvg) and as G-code, like any picture.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

use std::f64::consts::TAU;
use zetafill_cli::model::picture::{Item, Shape};
use zetafill_cli::model::slices::{self, section, SliceError, SliceOptions};
use zetafill_cli::model::solid::{axis_angle as rotation, Region3, Solid, SolidKind};
use zetafill_cli::model::{Drawing, Path};
use zetafill_cli::output::{gcode, machine::Machine, svg};

/// One solid of every kind, turned, apart from each other in a 100 mm box.
fn scene() -> Vec<Solid> {
    let kinds = [
        SolidKind::Sphere { radius: 9.0 },
        SolidKind::Shell { outer: 9.0, inner: 6.0 },
        SolidKind::Cube { half_side: 6.0 },
        SolidKind::Tetrahedron { circumradius: 9.0 },
        SolidKind::Octahedron { circumradius: 9.0 },
        SolidKind::Torus { major: 7.0, minor: 2.5 },
        SolidKind::BeadTorus {
            major: 7.0,
            minor: 2.5,
            beads: 12,
        },
        SolidKind::Cube { half_side: 6.0 },
    ];
    kinds
        .iter()
        .enumerate()
        .map(|(i, kind)| {
            let f = i as f64;
            Solid {
                centre: [15.0 + 25.0 * (f % 3.0), 15.0 + 25.0 * ((f / 3.0).floor() % 3.0), 20.0 + 7.0 * f],
                // The last cube stays axis-aligned: a face lies in some cutting planes' way.
                rotation: if i == 7 {
                    zetafill_cli::model::solid::IDENTITY
                } else {
                    rotation([1.0, 0.3 * f - 1.0, 0.5], 0.4 + 0.9 * f)
                },
                kind: *kind,
            }
        })
        .collect()
}

/// The pieces of an item's outline.
fn pieces(item: &Item) -> Vec<Path> {
    match &item.shape {
        Shape::Circle { c, r } => vec![Path::circle(*c, *r)],
        _ => item.strokes(),
    }
}

/// Points along a piece.
fn along(p: &Path) -> Vec<[f64; 2]> {
    match p {
        Path::Arc {
            center,
            radius,
            start,
            sweep,
        } => (0..=48)
            .map(|k| {
                let a = start + sweep.clamp(-TAU, TAU) * f64::from(k) / 48.0;
                [center[0] + radius * a.cos(), center[1] + radius * a.sin()]
            })
            .collect(),
        Path::Polyline { points, closed } => {
            let n = points.len();
            let segs = if *closed { n } else { n.saturating_sub(1) };
            (0..segs)
                .flat_map(|i| {
                    let (a, b) = (points[i], points[(i + 1) % n]);
                    (0..8).map(move |k| {
                        let t = f64::from(k) / 8.0;
                        [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
                    })
                })
                .collect()
        }
    }
}

/// How many times the ray from `q` towards +x crosses the piece.
fn crossings(p: &Path, q: [f64; 2]) -> usize {
    match p {
        Path::Arc {
            center,
            radius,
            start,
            sweep,
        } => {
            let dy = q[1] - center[1];
            if dy.abs() >= *radius {
                return 0;
            }
            let dx = (radius * radius - dy * dy).sqrt();
            [center[0] - dx, center[0] + dx]
                .iter()
                .filter(|&&x| x > q[0])
                .filter(|&&x| {
                    let a = dy.atan2(x - center[0]);
                    sweep.abs() >= TAU || {
                        let (s, w) = if *sweep >= 0.0 { (*start, *sweep) } else { (start + sweep, -sweep) };
                        (a - s).rem_euclid(TAU) <= w
                    }
                })
                .count()
        }
        Path::Polyline { points, .. } => {
            let n = points.len();
            (0..n)
                .filter(|&i| {
                    let (a, b) = (points[i], points[(i + 1) % n]);
                    (a[1] > q[1]) != (b[1] > q[1]) && a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]) > q[0]
                })
                .count()
        }
    }
}

/// Whether `item` is the section of `s` at height `z`: its outline on the surface (within
/// `slack` inside it), and the points of a grid inside the outline exactly when inside the
/// solid, up to `slack`. The error says where it is not.
fn is_section(s: &Solid, z: f64, item: &Item, slack: f64) -> Result<(), String> {
    let ps = pieces(item);
    for p in &ps {
        for q in along(p) {
            let x = [q[0], q[1], z];
            if !s.contains(x, 1e-9) || s.contains(x, -(slack + 1e-9)) {
                return Err(format!("outline point {q:?} is not on the surface of {:?}", s.kind));
            }
        }
    }
    let r = s.kind.bounding_radius();
    let n = 60;
    for i in 0..n {
        for j in 0..n {
            // Irrational offsets keep the grid off vertices and arc ends.
            let q = [
                s.centre[0] - r + 2.0 * r * (f64::from(i) + 0.5 + 0.1 * 2f64.sqrt()) / f64::from(n),
                s.centre[1] - r + 2.0 * r * (f64::from(j) + 0.5 + 0.1 * 3f64.sqrt()) / f64::from(n),
            ];
            let x = [q[0], q[1], z];
            let drawn = ps.iter().map(|p| crossings(p, q)).sum::<usize>() % 2 == 1;
            if s.contains(x, -(slack + 1e-6)) && !drawn {
                return Err(format!("{q:?} is inside {:?} but outside the outline", s.kind));
            }
            if !s.contains(x, slack + 1e-6) && drawn {
                return Err(format!("{q:?} is outside {:?} but inside the outline", s.kind));
            }
        }
    }
    Ok(())
}

/// The heights that cut each solid at several depths.
fn heights(s: &Solid) -> Vec<f64> {
    let r = s.kind.bounding_radius();
    (1..12).map(|k| s.centre[2] - r + 2.0 * r * f64::from(k) / 12.0 + 1e-3).collect()
}

#[test]
fn every_section_is_the_exact_cross_section() {
    let tol = 0.01;
    let mut checked = 0;
    for s in scene() {
        let slack = if matches!(s.kind, SolidKind::Torus { .. }) { tol } else { 0.0 };
        for z in heights(&s) {
            if let Some(item) = section(&s, z, tol) {
                is_section(&s, z, &item, slack).unwrap_or_else(|e| panic!("z = {z}: {e}"));
                checked += 1;
            }
        }
        let r = s.kind.bounding_radius();
        assert_eq!(section(&s, s.centre[2] + r + 0.1, tol), None, "a plane above misses");
    }
    assert!(checked > 60, "{checked} sections");
}

#[test]
fn broken_sections_are_caught() {
    let solids = scene();
    let z_of = |s: &Solid| s.centre[2] + 0.3;
    // A circle 2% too large.
    let s = &solids[0];
    let Some(Item {
        shape: Shape::Circle { c, r },
        ..
    }) = section(s, z_of(s), 0.01)
    else {
        panic!("a circle")
    };
    let big = Item::new(Shape::Circle { c, r: r * 1.02 });
    assert!(is_section(s, z_of(s), &big, 0.0).is_err());
    // A shell without its hole.
    let s = &solids[1];
    let no_hole = Item::new(Shape::Circle {
        c: [s.centre[0], s.centre[1]],
        r: (81.0f64 - 0.09).sqrt(),
    });
    assert!(is_section(s, z_of(s), &no_hole, 0.0).is_err());
    // A polygon with one vertex moved out.
    let s = &solids[3];
    let Some(Item {
        shape: Shape::Polygon(mut vs),
        ..
    }) = section(s, z_of(s), 0.01)
    else {
        panic!("a polygon")
    };
    vs[0] = [vs[0][0] + 0.5, vs[0][1] + 0.5];
    assert!(is_section(s, z_of(s), &Item::new(Shape::Polygon(vs)), 0.0).is_err());
    // A bead torus's outline with one arc left out.
    let s = &solids[6];
    let z = s.centre[2] + 0.2;
    let Some(Item {
        shape: Shape::Loops(mut loops),
        ..
    }) = section(s, z, 0.01)
    else {
        panic!("loops")
    };
    let longest = (0..loops.len()).max_by_key(|k| loops[*k].len()).expect("a loop");
    loops[longest].remove(0);
    assert!(is_section(s, z, &Item::new(Shape::Loops(loops)).evenodd(), 0.0).is_err());
}

#[test]
fn discs_union_into_outlines_with_holes() {
    // A ring of eight overlapping discs: an outer loop and a hole.
    let discs: Vec<([f64; 2], f64)> = (0..8)
        .map(|k| {
            let a = TAU * f64::from(k) / 8.0;
            ([10.0 * a.cos(), 10.0 * a.sin()], 4.5)
        })
        .collect();
    let loops = slices::disc_union(&discs);
    assert_eq!(loops.len(), 2);
    assert!(loops.iter().all(|l| l.len() == 8));
    // A disc inside another, and an equal pair, add nothing.
    let loops = slices::disc_union(&[([0.0, 0.0], 5.0), ([1.0, 0.0], 2.0), ([0.0, 0.0], 5.0)]);
    assert_eq!(loops, vec![vec![Path::circle([0.0, 0.0], 5.0)]]);
}

#[test]
fn random_disc_unions_are_closed_loops_around_exactly_the_union() {
    let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..40 {
        let discs: Vec<([f64; 2], f64)> = (0..25).map(|_| ([rnd() * 20.0, rnd() * 20.0], 0.5 + 3.0 * rnd())).collect();
        let loops = slices::disc_union(&discs);
        for l in &loops {
            for (k, p) in l.iter().enumerate() {
                let next = &l[(k + 1) % l.len()];
                let gap = (p.end_point()[0] - next.start_point()[0]).hypot(p.end_point()[1] - next.start_point()[1]);
                assert!(gap < 1e-9, "a loop is broken by {gap}");
            }
        }
        let pieces: Vec<Path> = loops.into_iter().flatten().collect();
        for i in 0..50 {
            for j in 0..50 {
                let q = [
                    -4.0 + 28.0 * (f64::from(i) + 0.3 * 2f64.sqrt()) / 50.0,
                    -4.0 + 28.0 * (f64::from(j) + 0.2 * 3f64.sqrt()) / 50.0,
                ];
                let depth = discs
                    .iter()
                    .map(|(c, r)| r - (q[0] - c[0]).hypot(q[1] - c[1]))
                    .fold(f64::NEG_INFINITY, f64::max);
                if depth.abs() < 1e-6 {
                    continue;
                }
                let drawn = pieces.iter().map(|p| crossings(p, q)).sum::<usize>() % 2 == 1;
                assert_eq!(drawn, depth > 0.0, "{q:?}");
            }
        }
    }
}

#[test]
fn sheets_stack_with_marks_and_write_as_svg_and_gcode() {
    let solids = scene();
    let region = Region3::Box {
        w: 100.0,
        h: 100.0,
        d: 100.0,
    };
    let sheets = slices::slices(&solids, &region, &SliceOptions::new(7.0)).expect("slices");
    assert_eq!(sheets.len(), 15, "ceil(100 / 7) sheets");
    let marks = &sheets[0].picture.layers[2];
    let mut cut = 0;
    for (k, sheet) in sheets.iter().enumerate() {
        assert_eq!(sheet.index, k);
        assert!((sheet.z - (3.5 + 7.0 * k as f64)).abs() < 1e-9);
        let ids: Vec<_> = sheet.picture.layers.iter().map(|l| l.id.clone().unwrap_or_default()).collect();
        assert_eq!(ids, ["outline", "parts", "marks"]);
        assert_eq!(&sheet.picture.layers[2], marks, "the same marks on every sheet");
        let expected: Vec<Item> = solids.iter().filter_map(|s| section(s, sheet.z, 0.01)).collect();
        assert_eq!(sheet.picture.layers[1].items, expected);
        cut += expected.len();
        let bytes = svg::write(&sheet.picture);
        usvg::Tree::from_data(&bytes, &usvg::Options::default()).expect("usvg reads the sheet");
        assert_eq!(bytes, svg::write(&sheet.picture), "byte-identical");
        let machine = Machine::builtin("grbl-laser").expect("built-in");
        let pens: Vec<(String, Drawing)> = sheet
            .picture
            .pens()
            .into_iter()
            .map(|(pen, d)| {
                (
                    pen,
                    Drawing {
                        paths: d.paths.iter().map(|p| p.transformed(1.0, 1.0, 20.0, 20.0)).collect(),
                    },
                )
            })
            .collect();
        gcode::write_pens(&pens, &machine, &gcode::GcodeOptions::new(&machine)).expect("G-code for a laser");
    }
    assert!(cut >= solids.len(), "every solid is cut at least once");
    let all = slices::stacked(&sheets).expect("sheets");
    assert_eq!(all.layers.len(), 15);
    assert!(svg::write(&all).windows(16).any(|w| w == b"sheet 15 z=101.5"));
    // A ball's sheets are circles of the ball's section.
    let ball = slices::slices(&[], &Region3::Ball { r: 10.0 }, &SliceOptions::new(5.0)).expect("slices");
    let Shape::Circle { r, .. } = ball[0].picture.layers[0].items[0].shape else {
        panic!("a circle")
    };
    assert!((r - (100.0f64 - 7.5 * 7.5).sqrt()).abs() < 1e-12);
}

#[test]
fn the_stacked_svg_reruns_byte_for_byte_and_is_pinned() {
    use sha2::{Digest, Sha256};
    let region = Region3::BoxMinusBall {
        w: 100.0,
        h: 100.0,
        d: 100.0,
        r: 20.0,
    };
    let svg_of =
        || svg::write(&slices::stacked(&slices::slices(&scene(), &region, &SliceOptions::new(4.0)).expect("slices")).expect("sheets"));
    let (a, b) = (svg_of(), svg_of());
    assert!(a == b, "byte-identical reruns");
    let digest: String = Sha256::digest(&a).iter().map(|b| format!("{b:02x}")).collect();
    // Re-mint by copying the digest from the failure, in a commit that says why it changed.
    assert_eq!(
        digest, "0b102be807cb27c4ec6c2ab86a6ff3b7e6161f10c07dcc0743ba4d918c97ed4b",
        "the slices' SVG changed"
    );
}

#[test]
fn bad_thicknesses_are_refused() {
    let region = Region3::Box { w: 10.0, h: 10.0, d: 10.0 };
    for t in [0.0, -1.0, f64::NAN, 10.5] {
        assert!(
            matches!(
                slices::slices(&[], &region, &SliceOptions::new(t)),
                Err(SliceError::Thickness { .. })
            ),
            "{t}"
        );
    }
    assert!(matches!(
        slices::slices(&[], &region, &SliceOptions::new(1e-4)),
        Err(SliceError::TooMany(_))
    ));
    assert_eq!(slices::slices(&[], &region, &SliceOptions::new(10.0)).expect("one sheet").len(), 1);
}
