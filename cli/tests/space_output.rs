//! The 3D writers read back by independent libraries: binary STL by `stl_io`, OBJ by `tobj`,
//! GLB by the `gltf` crate and by the Khronos glTF validator (node); every mesh closed and
//! oriented and inside its exact solid; the render decoded; byte-identical reruns pinned by
//! SHA-256. Each checker has a twin fed a broken input that must fail.

use sha2::{Digest, Sha256};
use std::collections::HashMap;
use std::io::Cursor;
use std::path::Path;
use std::process::Command;
use zetafill_cli::model::solid::{axis_angle as rotation, Region3, Solid, SolidKind};
use zetafill_cli::output::mesh::{local_mesh, MeshOptions};
use zetafill_cli::output::render3d::{self, Cut, RenderOptions};
use zetafill_cli::output::{glb, obj, stl};

/// One solid of every kind, turned, in a 100 mm box, apart from each other.
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
        SolidKind::Sphere { radius: 0.4 },
        SolidKind::Cube { half_side: 0.3 },
    ];
    kinds
        .iter()
        .enumerate()
        .map(|(i, kind)| {
            let f = i as f64;
            Solid {
                centre: [15.0 + 25.0 * (f % 3.0), 15.0 + 25.0 * ((f / 3.0).floor() % 3.0), 20.0 + 7.0 * f],
                rotation: rotation([1.0, 0.3 * f - 1.0, 0.5], 0.4 + 0.9 * f),
                kind: *kind,
            }
        })
        .collect()
}

fn region() -> Region3 {
    Region3::Box {
        w: 100.0,
        h: 100.0,
        d: 100.0,
    }
}

/// Whether every edge of these triangles is used once in each direction (a closed, oriented
/// surface); the error names the first edge that is not.
fn closed_and_oriented(faces: &[[usize; 3]]) -> Result<(), String> {
    let mut edges: HashMap<(usize, usize), u32> = HashMap::new();
    for f in faces {
        for k in 0..3 {
            *edges.entry((f[k], f[(k + 1) % 3])).or_default() += 1;
        }
    }
    for (&(a, b), &n) in &edges {
        if n != 1 || edges.get(&(b, a)) != Some(&1) {
            return Err(format!("edge {a}->{b} used {n} times, {b}->{a} {:?} times", edges.get(&(b, a))));
        }
    }
    Ok(())
}

/// The triangles of a binary STL as 32-bit corners, read by hand (for the inside check).
fn stl_triangles(bytes: &[u8]) -> Vec<[[f32; 3]; 3]> {
    let n = u32::from_le_bytes(bytes[80..84].try_into().expect("4 bytes")) as usize;
    assert_eq!(bytes.len(), 84 + 50 * n, "a binary STL is 84 + 50 n bytes");
    let f = |at: usize| f32::from_le_bytes(bytes[at..at + 4].try_into().expect("4 bytes"));
    (0..n)
        .map(|i| {
            let base = 84 + 50 * i + 12;
            [0, 1, 2].map(|v| [0, 1, 2].map(|c| f(base + 12 * v + 4 * c)))
        })
        .collect()
}

/// Points spread over a triangle: corners, edges, inside.
fn samples(t: [[f64; 3]; 3]) -> Vec<[f64; 3]> {
    let k = 5;
    let mut out = Vec::new();
    for i in 0..=k {
        for j in 0..=k - i {
            let (a, b) = (i as f64 / k as f64, j as f64 / k as f64);
            out.push([0, 1, 2].map(|c| t[0][c] * (1.0 - a - b) + t[1][c] * a + t[2][c] * b));
        }
    }
    out
}

/// Whether every triangle, taken in file order with each solid's count of triangles, lies
/// inside its solid (no tolerance); the error names the solid.
fn inside(solids: &[Solid], triangles: &[[[f32; 3]; 3]], opt: &MeshOptions) -> Result<(), String> {
    let mut next = 0;
    for (i, s) in solids.iter().enumerate() {
        let count = local_mesh(&s.kind, opt).map_err(|e| e.to_string())?.triangles.len();
        for t in &triangles[next..next + count] {
            let t = t.map(|p| p.map(f64::from));
            if let Some(p) = samples(t).into_iter().find(|p| !s.contains(*p, 0.0)) {
                return Err(format!("solid {i} ({:?}): mesh point {p:?} outside", s.kind));
            }
        }
        next += count;
    }
    (next == triangles.len()).then_some(()).ok_or_else(|| "triangles left over".into())
}

fn sha(bytes: &[u8]) -> String {
    Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}

#[test]
fn stl_is_read_back_closed_oriented_and_inside() {
    let solids = scene();
    let opt = MeshOptions::for_scene(&solids, 24);
    let bytes = stl::to_bytes(&solids, &opt).expect("writes");
    let mesh = stl_io::read_stl(&mut Cursor::new(&bytes)).expect("stl_io reads it");
    mesh.validate().expect("stl_io finds it closed");
    let faces: Vec<[usize; 3]> = mesh.faces.iter().map(|f| f.vertices).collect();
    closed_and_oriented(&faces).expect("closed and oriented");
    let triangles = stl_triangles(&bytes);
    assert_eq!(triangles.len(), mesh.faces.len());
    inside(&solids, &triangles, &opt).expect("every mesh inside its solid");
    // Normals point out of the material (the centroid of a sphere's triangle, seen from its
    // centre, is along the normal).
    let n = mesh.faces[0].normal.0;
    assert!(n.iter().map(|x| x * x).sum::<f32>() > 0.99);

    // The twins: a missing triangle, a flipped one, a mesh grown 1% past its solid.
    let mut broken = faces.clone();
    broken.remove(7);
    assert!(closed_and_oriented(&broken).is_err(), "a missing triangle must be found");
    let mut cut = bytes.clone();
    let n = u32::from_le_bytes(cut[80..84].try_into().expect("4 bytes")) - 1;
    cut[80..84].copy_from_slice(&n.to_le_bytes());
    cut.truncate(cut.len() - 50);
    let short = stl_io::read_stl(&mut Cursor::new(&cut)).expect("still an STL");
    assert!(short.validate().is_err(), "stl_io must find the hole");
    let mut flipped = faces.clone();
    flipped[3].swap(1, 2);
    assert!(closed_and_oriented(&flipped).is_err(), "a flipped triangle must be found");
    let grown: Vec<_> = solids
        .iter()
        .map(|s| Solid {
            kind: match s.kind {
                SolidKind::Sphere { radius } => SolidKind::Sphere { radius: radius * 1.01 },
                k => k,
            },
            ..*s
        })
        .collect();
    let big = stl_triangles(&stl::to_bytes(&grown, &opt).expect("writes"));
    assert!(inside(&solids, &big, &opt).is_err(), "a mesh outside its solid must be found");
}

#[test]
fn solids_that_cannot_be_meshed_are_named() {
    let mut solids = scene();
    solids[4].rotation[2] = [0.0, 0.0, -1.0];
    let opt = MeshOptions::new(16);
    let e = stl::to_bytes(&solids, &opt).expect_err("a reflection is not a rotation");
    assert!(e.to_string().starts_with("solid 4:"), "{e}");
    assert!(
        glb::to_bytes(&solids, 16).is_err()
            && render3d::pixels(
                &solids,
                &region(),
                &RenderOptions {
                    width: 8,
                    height: 8,
                    samples: 1,
                    cut: Cut::None
                }
            )
            .is_err()
    );
    let mut solids = scene();
    solids[2].centre[1] = f64::NAN;
    assert!(obj::to_bytes(&solids, &opt).is_err() && glb::to_bytes(&solids, 16).is_err());
    let mut solids = scene();
    solids[1].kind = SolidKind::Shell { outer: 9.0, inner: 8.99 };
    assert!(stl::to_bytes(&solids, &opt)
        .expect_err("too thin")
        .to_string()
        .contains("use more segments"));
    assert!(stl::to_bytes(&scene(), &MeshOptions::new(2000)).is_err(), "an absurd resolution");
}

#[test]
fn tori_meshed_on_their_surface_leave_the_tube() {
    // The twin of the inside check for the shrink: the same torus written with the tube of
    // its mesh put back to the full radius is caught.
    let s = Solid::new([50.0, 50.0, 50.0], SolidKind::Torus { major: 7.0, minor: 2.5 });
    let opt = MeshOptions::new(16);
    let tube = zetafill_cli::output::mesh::torus_mesh_tube(7.0, 2.5, 16).expect("a tube");
    assert!(tube < 2.5);
    let naive = zetafill_cli::output::mesh::torus_mesh(7.0, 2.5, 16).mapped(|q| s.to_world(q));
    let tris: Vec<_> = (0..naive.triangles.len())
        .map(|i| naive.corners(i).map(|p| p.map(|c| c as f32)))
        .collect();
    assert!(inside(&[s], &tris, &opt).is_err());
}

#[test]
fn obj_is_read_back_by_tobj_with_the_stl_points() {
    let solids = scene();
    let opt = MeshOptions::for_scene(&solids, 24);
    let bytes = obj::to_bytes(&solids, &opt).expect("writes");
    let load = tobj::LoadOptions {
        single_index: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj_buf(&mut Cursor::new(&bytes), &load, |_| Err(tobj::LoadError::OpenFileFailed)).expect("tobj reads it");
    assert_eq!(models.len(), solids.len());
    let stl = stl_triangles(&stl::to_bytes(&solids, &opt).expect("writes"));
    let mut next = 0;
    for (i, m) in models.iter().enumerate() {
        assert_eq!(m.name, format!("solid_{}", i + 1));
        let faces: Vec<[usize; 3]> = m.mesh.indices.chunks(3).map(|c| [c[0], c[1], c[2]].map(|k| k as usize)).collect();
        closed_and_oriented(&faces).expect("closed and oriented");
        for f in &faces {
            let corners = f.map(|k| [0, 1, 2].map(|c| m.mesh.positions[3 * k + c]));
            assert_eq!(corners, stl[next], "OBJ and STL carry the same points");
            next += 1;
        }
    }
    assert_eq!(next, stl.len());
}

/// The Khronos validator's report on a GLB: (errors, warnings, the report).
fn validate_glb(bytes: &[u8]) -> (u64, u64, String) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scripts/node/node_modules");
    assert!(
        dir.join("gltf-validator").exists(),
        "the glTF validator is not installed: run `(cd scripts/node && npm ci)` or `bash scripts/test-all.sh`"
    );
    let tmp = tempfile::tempdir().expect("a temporary folder");
    let file = tmp.path().join("scene.glb");
    std::fs::write(&file, bytes).expect("written");
    let script = "const v = require('gltf-validator'); const fs = require('fs');\
        v.validateBytes(new Uint8Array(fs.readFileSync(process.argv[1])))\
        .then(r => console.log(JSON.stringify(r.issues)))\
        .catch(e => { console.error(e); process.exit(2); });";
    let out = Command::new("node")
        .env("NODE_PATH", &dir)
        .args(["-e", script])
        .arg(&file)
        .output()
        .expect("node runs (install nodejs)");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report = String::from_utf8_lossy(&out.stdout).to_string();
    let issues: serde_json::Value = serde_json::from_str(&report).expect("a JSON report");
    let n = |k: &str| issues[k].as_u64().expect("a count");
    (n("numErrors"), n("numWarnings"), report)
}

#[test]
fn glb_loads_in_gltf_and_passes_the_khronos_validator() {
    let mut solids = scene();
    // More of the same shapes: instances share their mesh.
    solids.extend(scene().iter().map(|s| Solid {
        centre: s.centre.map(|c| 100.0 - c),
        ..*s
    }));
    let bytes = glb::to_bytes(&solids, 24).expect("writes");
    let g = gltf::Gltf::from_slice(&bytes).expect("the gltf crate reads it");
    assert_eq!(g.nodes().count(), solids.len() + 1);
    assert_eq!(
        g.meshes().count(),
        7,
        "one mesh per kind and shape ratio (two sphere and two cube sizes share)"
    );
    for n in g.nodes().skip(1) {
        let (_, r, s) = n.transform().decomposed();
        assert!((r.iter().map(|x| x * x).sum::<f32>() - 1.0).abs() < 1e-6);
        assert!(s[0] > 0.0 && s[0] == s[1] && s[1] == s[2]);
        assert!(n.mesh().is_some());
    }
    let (errors, warnings, report) = validate_glb(&bytes);
    assert_eq!((errors, warnings), (0, 0), "{report}");

    // The twin: a GLB whose JSON promises more vertices than its buffer holds.
    let at = bytes.windows(9).position(|w| w == b"\"count\":4").expect("a count in the JSON");
    let mut broken = bytes.clone();
    broken[at + 8] = b'9';
    let (errors, _, _) = validate_glb(&broken);
    assert!(errors > 0, "the validator must reject a wrong accessor count");
}

#[test]
fn writers_rerun_byte_for_byte_and_are_pinned() {
    let solids = scene();
    let opt = MeshOptions::for_scene(&solids, 16);
    let render = RenderOptions {
        width: 160,
        height: 120,
        samples: 2,
        cut: Cut::Octant,
    };
    let outputs = |s: &[Solid]| {
        [
            stl::to_bytes(s, &opt).expect("stl"),
            obj::to_bytes(s, &opt).expect("obj"),
            glb::to_bytes(s, 16).expect("glb"),
            render3d::render(s, &region(), &render).expect("png"),
        ]
    };
    let (a, b) = (outputs(&solids), outputs(&solids));
    assert_eq!(a, b);
    let digests: Vec<String> = a.iter().map(|x| sha(x)).collect();
    // Re-mint by printing `digests` after a change that a commit explains.
    let pinned = [
        "b3ec9492b84d199039c76c093b8686203715ca4a679f5e5b00142493aabe63c8",
        "53c7909162758727e5987225853c395629fea50aa898392e30c50353164e8dc6",
        "7613659171699425f9259bebb9b5ec99d80433d591a502a5e875f7dedb3227e9",
        "36c3d02577aade8bf03da218a157e76ad8c38cf3a9ebba345b1db187adba28c6",
    ];
    assert!(digests == pinned, "a 3D output changed (STL, OBJ, GLB, PNG): {digests:?}");
}

#[test]
fn renders_show_the_solids_with_depth_and_cut_away() {
    // Two equal spheres, one near the camera and one far: the far one fades.
    let region = Region3::Box {
        w: 100.0,
        h: 100.0,
        d: 100.0,
    };
    let near = Solid::new([80.0, 20.0, 80.0], SolidKind::Sphere { radius: 10.0 });
    let far = Solid::new([20.0, 80.0, 20.0], SolidKind::Sphere { radius: 10.0 });
    let opt = RenderOptions {
        width: 200,
        height: 200,
        samples: 1,
        cut: Cut::None,
    };
    let bg = render3d::pixels(&[], &region, &opt).expect("renders");
    assert!(bg.chunks(3).all(|p| p == &bg[..3]), "no solids, only background");
    let both = render3d::pixels(&[near, far], &region, &opt).expect("renders");
    let changed = |a: &[u8]| a.chunks(3).zip(bg.chunks(3)).filter(|(x, y)| x != y).count();
    let only_near = render3d::pixels(&[near], &region, &opt).expect("renders");
    let only_far = render3d::pixels(&[far], &region, &opt).expect("renders");
    assert!(changed(&only_near) > changed(&only_far), "the near sphere looks bigger");
    assert!(changed(&only_far) > 100 && changed(&both) > changed(&only_near));
    // Contrast against the background: the far sphere's pixels are closer to it.
    let contrast = |img: &[u8]| {
        let px: Vec<i64> = img
            .chunks(3)
            .zip(bg.chunks(3))
            .filter(|(x, y)| x != y)
            .map(|(x, y)| (0..3).map(|k| (i64::from(x[k]) - i64::from(y[k])).abs()).sum())
            .collect();
        px.iter().sum::<i64>() / px.len().max(1) as i64
    };
    assert!(contrast(&only_near) > contrast(&only_far) + 10, "depth cue");
    // The cut-away removes the near sphere (its centre is in the octant facing the camera).
    let cut = render3d::pixels(&[near, far], &region, &RenderOptions { cut: Cut::Octant, ..opt }).expect("renders");
    let mask = |img: &[u8]| img.chunks(3).map(|p| p != &bg[..3]).collect::<Vec<bool>>();
    assert!(mask(&cut) == mask(&only_far), "the cut-away leaves exactly the far sphere");
    let png = render3d::render(&[near, far], &region, &opt).expect("encodes");
    let decoder = png::Decoder::new(Cursor::new(png));
    let reader = decoder.read_info().expect("a PNG");
    assert_eq!((reader.info().width, reader.info().height), (200, 200));
    assert!(render3d::render(&[], &region, &RenderOptions { width: 0, ..opt }).is_err());
}

#[test]
fn ten_thousand_solids_render() {
    // A grid of small solids of every kind: the uniform grid keeps this quick (no clock is
    // asserted; the suite's time shows it).
    let kinds = scene();
    let solids: Vec<Solid> = (0..10_000)
        .map(|i| {
            let f = f64::from(i);
            let k = kinds[i as usize % kinds.len()].kind;
            let s = 1.5 / k.bounding_radius();
            let kind = match k {
                SolidKind::Sphere { radius } => SolidKind::Sphere { radius: radius * s },
                SolidKind::Shell { outer, inner } => SolidKind::Shell {
                    outer: outer * s,
                    inner: inner * s,
                },
                SolidKind::Cube { half_side } => SolidKind::Cube { half_side: half_side * s },
                SolidKind::Tetrahedron { circumradius } => SolidKind::Tetrahedron {
                    circumradius: circumradius * s,
                },
                SolidKind::Octahedron { circumradius } => SolidKind::Octahedron {
                    circumradius: circumradius * s,
                },
                SolidKind::Torus { major, minor } => SolidKind::Torus {
                    major: major * s,
                    minor: minor * s,
                },
                SolidKind::BeadTorus { major, minor, beads } => SolidKind::BeadTorus {
                    major: major * s,
                    minor: minor * s,
                    beads,
                },
            };
            Solid {
                centre: [
                    2.5 + 5.0 * (f % 20.0),
                    2.5 + 5.0 * ((f / 20.0).floor() % 20.0),
                    2.5 + 4.0 * (f / 400.0).floor(),
                ],
                rotation: rotation([1.0, 2.0, 3.0], f),
                kind,
            }
        })
        .collect();
    let opt = RenderOptions {
        width: 320,
        height: 240,
        samples: 1,
        cut: Cut::Octant,
    };
    let img = render3d::pixels(&solids, &region(), &opt).expect("renders");
    assert_eq!(img.len(), 320 * 240 * 3);
}

/// Bug pinned here: the GLB keyed its meshes by the bits of a solid's ratio of radii, which is
/// computed from the two radii, so shells of one `--shape` at different sizes got ratios one
/// unit in the last place apart (0.3 and 0.29999999999999993) and one mesh each, though their
/// vertices round to the same 32-bit floats. A whole fill of them now shares one mesh; a different ratio (the control)
/// still gets its own.
#[test]
fn glb_ratios_that_differ_in_the_last_bit_share_one_mesh() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path();
    let run = |shape: &str, out: &str| {
        let o = Command::new(env!("CARGO_BIN_EXE_zetafill"))
            .args([
                "space",
                "-q",
                "--shape",
                shape,
                "--c",
                "1.15",
                "--n-offset",
                "3",
                "--count",
                "60",
                "-o",
                out,
            ])
            .current_dir(d)
            .output()
            .expect("runs");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read(d.join(out)).expect("written")
    };
    let doc: serde_json::Value = serde_json::from_slice(&run("shell:0.45", "s.json")).expect("JSON");
    let ratios: std::collections::BTreeSet<u64> = doc["solids"]
        .as_array()
        .expect("solids")
        .iter()
        .map(|s| (s["inner_radius"].as_f64().unwrap_or(0.0) / s["size"].as_f64().unwrap_or(1.0)).to_bits())
        .collect();
    assert!(ratios.len() > 1, "the scene must hold ratios that differ in their bits: {ratios:?}");
    let meshes = |bytes: &[u8]| gltf::Gltf::from_slice(bytes).expect("the gltf crate reads it").meshes().count();
    assert_eq!(meshes(&run("shell:0.45", "s.glb")), 1, "one shell ratio, one mesh");
    assert_eq!(meshes(&run("mix:shell:0.45,shell:0.451", "m.glb")), 2, "two ratios, two meshes");
}
