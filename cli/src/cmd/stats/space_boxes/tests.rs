use super::*;

fn brute(space: &Space3, e: f64, solids: &[(SolidKind, V3, crate::model::solid::Mat3)]) -> u64 {
    let s = space.sides();
    let g = [Axis::new(s[0], e), Axis::new(s[1], e), Axis::new(s[2], e)];
    let mut inside = 0;
    for k in 0..g[2].n {
        for j in 0..g[1].n {
            for i in 0..g[0].n {
                let corners: Vec<V3> = (0..8)
                    .map(|m| {
                        [
                            if m & 1 == 0 { g[0].lo(i) } else { g[0].hi(i) },
                            if m & 2 == 0 { g[1].lo(j) } else { g[1].hi(j) },
                            if m & 4 == 0 { g[2].lo(k) } else { g[2].hi(k) },
                        ]
                    })
                    .collect();
                let hit = solids.iter().any(|(kind, c, m)| {
                    let solid = crate::model::solid::Solid {
                        centre: *c,
                        rotation: *m,
                        kind: *kind,
                    };
                    // A shell's hole may poke through a face between the corners: the
                    // box's nearest point to the centre must stay out of it.
                    let hole = match kind {
                        SolidKind::Shell { inner, .. } => {
                            let d2: f64 = (0..3)
                                .map(|a| {
                                    let v = c[a].clamp(g[a].lo([i, j, k][a]), g[a].hi([i, j, k][a])) - c[a];
                                    v * v
                                })
                                .sum();
                            d2 < (inner + MARGIN * 14.0).powi(2)
                        }
                        _ => false,
                    };
                    // A torus covers a box when one of its beads does.
                    if let SolidKind::BeadTorus { minor, .. } = kind {
                        return kind.bead_centres().iter().any(|b| {
                            let bead = crate::model::solid::Solid {
                                centre: solid.to_world(*b),
                                rotation: *m,
                                kind: SolidKind::Sphere { radius: *minor },
                            };
                            corners.iter().all(|p| bead.contains(*p, -MARGIN * 14.0))
                        });
                    }
                    !hole && corners.iter().all(|p| solid.contains(*p, -MARGIN * 14.0))
                });
                if hit {
                    inside += 1;
                }
            }
        }
    }
    inside
}

fn space(solids: &[(SolidKind, V3, crate::model::solid::Mat3)]) -> Space3 {
    let region = Region3::Box { w: 14.0, h: 14.0, d: 7.0 };
    let margin = MARGIN * 14.0;
    let mut bodies = Vec::new();
    let mut sizes = Vec::new();
    for (k, c, m) in solids {
        bodies.push(body(k, *c, m, margin));
        sizes.push(2.0 * k.bounding_radius());
    }
    Space3 {
        region,
        periodic: false,
        bodies,
        sizes,
    }
}

/// The solids are disjoint, as in a fill, and the same margin shrinks them in both counts.
#[test]
fn rows_count_what_corners_count() {
    let m = rotation([0.9, 0.3, -0.2, 0.25]);
    let solids = vec![
        (SolidKind::Sphere { radius: 2.3 }, [3.0, 3.0, 3.2], m),
        (SolidKind::Cube { half_side: 1.4 }, [8.0, 2.6, 2.5], m),
        (SolidKind::Tetrahedron { circumradius: 2.0 }, [2.5, 8.0, 2.4], m),
        (SolidKind::Octahedron { circumradius: 2.0 }, [8.0, 8.0, 2.3], m),
        (SolidKind::Shell { outer: 1.9, inner: 1.1 }, [12.0, 5.0, 3.0], m),
        (
            SolidKind::BeadTorus {
                major: 1.6,
                minor: 0.7,
                beads: 9,
            },
            [5.0, 12.0, 4.6],
            m,
        ),
    ];
    let sp = space(&solids);
    for e in [2.5, 1.0, 0.5, 0.3, 0.17] {
        let (total, gasket) = sp.count(e);
        assert_eq!(total - gasket, brute(&sp, e, &solids), "e = {e}");
    }
}

#[test]
fn the_brute_count_can_fail() {
    // A sphere grown by a box's diagonal covers boxes the real one does not.
    let m = rotation([1.0, 0.0, 0.0, 0.0]);
    let solids = vec![(SolidKind::Sphere { radius: 2.3 }, [3.0, 3.1, 3.2], m)];
    let grown = vec![(SolidKind::Sphere { radius: 2.3 + 0.9 }, [3.0, 3.1, 3.2], m)];
    let (total, gasket) = space(&solids).count(0.5);
    assert_ne!(total - gasket, brute(&space(&grown), 0.5, &grown));
}

#[test]
fn ball_regions_count_the_boxes_that_meet_them() {
    let sp = Space3 {
        region: Region3::Ball { r: 1.0 },
        periodic: false,
        bodies: Vec::new(),
        sizes: Vec::new(),
    };
    // At box side 1 all 8 boxes meet the ball; at 0.4 the 8 corner boxes of 125 miss it.
    assert_eq!(sp.count(1.0).0, 8);
    assert_eq!(sp.count(0.4).0, 117);
}
