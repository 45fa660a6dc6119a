//! Unit tests of the wallpaper groups: the operations, wrapping, images and the largest disc.
extern crate std;
use super::*;
use std::vec::Vec;

fn walls() -> impl Iterator<Item = Wallpaper> {
    Group::ALL.iter().map(|&g| Wallpaper::new(g, 30.0, 20.0, 70.0).unwrap())
}

fn apply(iso: &Iso, p: [f64; 2]) -> [f64; 2] {
    let [a, b, c, d] = iso.m;
    [a * p[0] + b * p[1] + iso.t[0], c * p[0] + d * p[1] + iso.t[1]]
}

/// Whether `p` is a lattice vector of `w` (within 1e-9).
fn on_lattice(w: &Wallpaper, p: [f64; 2]) -> bool {
    let (ax, bx, by) = w.lattice();
    let l = p[1] / by;
    let k = (p[0] - l.round() * bx) / ax;
    (l - l.round()).abs() < 1e-9 && (k - k.round()).abs() < 1e-9
}

#[test]
fn the_operations_are_isometries_that_keep_the_lattice() {
    for w in walls() {
        let (ax, bx, by) = w.lattice();
        for k in 0..w.order() {
            let iso = w.iso(k).unwrap();
            let [a, b, c, d] = iso.m;
            // Orthogonal.
            assert!((a * a + c * c - 1.0).abs() < 1e-15 && (b * b + d * d - 1.0).abs() < 1e-15 && (a * b + c * d).abs() < 1e-15);
            // The linear part maps the lattice onto itself.
            let lin = Iso { m: iso.m, t: [0.0, 0.0] };
            assert!(on_lattice(&w, apply(&lin, [ax, 0.0])), "{:?} op {k}", w.group());
            assert!(on_lattice(&w, apply(&lin, [bx, by])), "{:?} op {k}", w.group());
        }
        assert!(w.iso(w.order()).is_none());
        assert_eq!(w.iso(0).unwrap().m, [1.0, 0.0, 0.0, 1.0]);
    }
}

#[test]
fn the_operations_form_a_group_modulo_the_lattice() {
    // The product of any two operations is a third one followed by a lattice translation,
    // and no two operations differ by a lattice translation alone.
    for w in walls() {
        let n = w.order();
        let ops: Vec<Iso> = (0..n).map(|k| w.iso(k).unwrap()).collect();
        let same = |x: &Iso, y: &Iso| {
            x.m.iter().zip(y.m.iter()).all(|(a, b)| (a - b).abs() < 1e-12) && on_lattice(&w, [x.t[0] - y.t[0], x.t[1] - y.t[1]])
        };
        for p in &ops {
            for q in &ops {
                let [a, b, c, d] = p.m;
                let [e, f, g, h] = q.m;
                let pq = Iso {
                    m: [a * e + b * g, a * f + b * h, c * e + d * g, c * f + d * h],
                    t: apply(p, q.t),
                };
                assert_eq!(ops.iter().filter(|o| same(o, &pq)).count(), 1, "{:?}", w.group());
            }
        }
        for (i, p) in ops.iter().enumerate() {
            for q in ops.iter().skip(i + 1) {
                assert!(!same(p, q), "{:?}", w.group());
            }
        }
    }
}

#[test]
fn mirrors_and_rotations_are_as_the_tables_list() {
    // (group, mirrors or glides, largest rotation order)
    let expect = [
        (Group::P1, 0, 1),
        (Group::P2, 0, 2),
        (Group::Pm, 1, 1),
        (Group::Pg, 1, 1),
        (Group::Cm, 1, 1),
        (Group::Pmm, 2, 2),
        (Group::Pmg, 2, 2),
        (Group::Pgg, 2, 2),
        (Group::Cmm, 2, 2),
        (Group::P4, 0, 4),
        (Group::P4m, 4, 4),
        (Group::P4g, 4, 4),
        (Group::P3, 0, 3),
        (Group::P3m1, 3, 3),
        (Group::P31m, 3, 3),
        (Group::P6, 0, 6),
        (Group::P6m, 6, 6),
    ];
    for (g, mirrors, rot) in expect {
        let w = Wallpaper::new(g, 30.0, 20.0, 70.0).unwrap();
        let ops: Vec<Iso> = (0..w.order()).map(|k| w.iso(k).unwrap()).collect();
        assert_eq!(ops.iter().filter(|o| o.mirrors()).count(), mirrors, "{g:?}");
        // The smallest rotation angle.
        let turn = ops
            .iter()
            .filter(|o| !o.mirrors() && o.m[0] < 1.0)
            .map(|o| libm::atan2(o.m[2], o.m[0]).abs())
            .fold(core::f64::consts::TAU, f64::min);
        let order = (core::f64::consts::TAU / turn).round() as usize;
        assert_eq!(if turn >= core::f64::consts::TAU { 1 } else { order }, rot, "{g:?}");
    }
}

#[test]
fn wrapping_stays_in_the_domain_and_moves_by_lattice_vectors() {
    for w in walls() {
        let (ax, _, by) = w.lattice();
        for i in 0..500 {
            let t = f64::from(i);
            let p = Point::new(libm::sin(t * 1.3) * 400.0, libm::cos(t * 0.7) * 300.0 - 17.0);
            let q = w.wrap(p);
            assert!(q.x >= 0.0 && q.x <= ax && q.y >= 0.0 && q.y <= by, "{:?} {p:?} -> {q:?}", w.group());
            assert!(on_lattice(&w, [q.x - p.x, q.y - p.y]), "{:?}", w.group());
        }
    }
}

#[test]
fn images_are_congruent_and_stay_counter_clockwise() {
    use crate::shape::ShapeKind;
    let star = ShapeKind::Star { points: 5, inner: 0.4 };
    for w in walls() {
        let c = Point::new(7.25, 3.5);
        let g = star.geo(c, 2.0, 0.3);
        let area = g.poly_area2();
        for k in 0..w.order() {
            let img = w.image(k, &g, c);
            assert!((img.poly_area2() - area).abs() < 1e-12, "{:?}", w.group());
            assert_eq!(img.vertices().len(), 10);
            let centre = w.image_centre(k, c);
            assert!(img
                .vertices()
                .iter()
                .all(|v| (v.dist2(centre) - g.vertices()[0].dist2(c)).abs() < 1e-9
                    || (v.dist2(centre) - g.vertices()[1].dist2(c)).abs() < 1e-9));
        }
    }
    // A blob (chiral) under a mirror is not a rotation of itself: the twin check.
    let w = Wallpaper::new(Group::Pm, 30.0, 20.0, 90.0).unwrap();
    let blob = ShapeKind::Blob { delta: 0.25 };
    let c = Point::new(10.0, 10.0);
    let g = blob.geo(c, 2.0, 0.7);
    let m = w.image(1, &g, c);
    // Mirrored: vertex k of the image is the mirror of vertex n-1-k.
    let (vs, ms) = (g.vertices(), m.vertices());
    let centre = w.image_centre(1, c);
    for (k, v) in vs.iter().enumerate() {
        let mv = ms[vs.len() - 1 - k];
        assert!((mv.x - (centre.x - (v.x - c.x))).abs() < 1e-12 && (mv.y - (centre.y + (v.y - c.y))).abs() < 1e-12);
    }
}

#[test]
fn the_largest_disc_is_the_groups_own() {
    // Known by hand: p1 on a square lattice, half its side; p2 on a square, a disc at
    // (a/4, a/4) sees its half-turn images at a / sqrt 2; pm, a quarter of the a/2 strip
    // between mirrors (when b is long); p4m, the incircle of its fundamental triangle of
    // legs a/2 (inradius a (2 - sqrt 2) / 4); p6m, the incircle of its 30-60-90 triangle.
    let a = 60.0;
    let disc = |g: Group, b: f64| Wallpaper::new(g, a, b, 90.0).unwrap().largest_disc();
    let near = |x: f64, y: f64| (x - y).abs() < 1e-9 * a;
    assert!(near(disc(Group::P1, a), a / 2.0));
    assert!(near(disc(Group::P2, a), a / 2.0 / libm::sqrt(2.0)));
    assert!(near(disc(Group::Pm, 200.0), a / 4.0));
    assert!(
        near(disc(Group::P4m, a), a * (2.0 - libm::sqrt(2.0)) / 4.0),
        "{} {}",
        disc(Group::P4m, a),
        a * (2.0 - libm::sqrt(2.0)) / 4.0
    );
    // p6m: the triangle with legs a/2 and a/(2 sqrt 3): inradius (leg1 + leg2 - hyp) / 2.
    let (l1, l2) = (a / 2.0, a / (2.0 * libm::sqrt(3.0)));
    let hyp = libm::sqrt(l1 * l1 + l2 * l2);
    assert!(near(disc(Group::P6m, a), (l1 + l2 - hyp) / 2.0));
    // A point on a rotation centre has its image on itself: no room at all.
    let w = Wallpaper::new(Group::P4, a, a, 90.0).unwrap();
    assert_eq!(w.orbit_gap(Point::new(0.0, 0.0)), 0.0);
    assert_eq!(w.orbit_gap(Point::new(a / 2.0, a / 2.0)), 0.0);
    assert!(w.orbit_gap(Point::new(a / 4.0, 0.0)) > 0.0);
}

#[test]
fn lattices_are_checked() {
    assert_eq!(Wallpaper::new(Group::P1, 0.0, 1.0, 60.0), Err(WallpaperError::Side));
    assert_eq!(Wallpaper::new(Group::P1, 1.0, f64::NAN, 60.0), Err(WallpaperError::Side));
    assert_eq!(Wallpaper::new(Group::Pm, 1.0, -1.0, 90.0), Err(WallpaperError::Side));
    assert_eq!(Wallpaper::new(Group::P2, 1.0, 1.0, 0.0), Err(WallpaperError::Angle));
    assert_eq!(Wallpaper::new(Group::P2, 1.0, 1.0, 180.0), Err(WallpaperError::Angle));
    assert_eq!(Wallpaper::new(Group::P2, 1.0, 1.0, f64::NAN), Err(WallpaperError::Angle));
    assert_eq!(Wallpaper::new(Group::P4, f64::INFINITY, 1.0, 90.0), Err(WallpaperError::Side));
    // Square and hexagonal lattices ignore b and the angle.
    assert!(Wallpaper::new(Group::P6m, 1.0, -5.0, 500.0).is_ok());
    // The areas.
    let h = Wallpaper::new(Group::P6m, 10.0, 0.0, 0.0).unwrap();
    assert_eq!(h.cell_area(), 10.0 * (10.0 * SQRT3_2));
    assert_eq!(h.fundamental_area(), 10.0 * (10.0 * SQRT3_2) / 12.0);
    let cm = Wallpaper::new(Group::Cm, 40.0, 30.0, 0.0).unwrap();
    assert_eq!((cm.cell_area(), cm.fundamental_area(), cm.cell()), (600.0, 300.0, (40.0, 30.0)));
    let ob = Wallpaper::new(Group::P2, 10.0, 20.0, 30.0).unwrap();
    let (ax, bx, by) = ob.lattice();
    assert_eq!(ax, 10.0);
    assert!(bx.abs() <= 5.0 && (by - 10.0).abs() < 1e-12);
}
