//! The CLI reports exactly what the core placed: the JSON of a run, parsed back, carries the
//! same bits as the core's own run of the same scene, and `--format digest` equals the core's
//! digest.

use zetafill_tests::{parse_fill, run_scene, scene_args, CANONICAL};

#[test]
fn json_round_trips_the_core_bits() {
    for scene in &CANONICAL {
        let mut args = scene_args(scene);
        args.extend(["-o".into(), "-".into()]);
        let a = parse_fill(&args);
        let (run, draw) = zetafill_cli::plan::fill::resolve_as(&a, zetafill_cli::plan::format::Format::Json)
            .unwrap_or_else(|e| panic!("{}: {e}", scene.name));
        let (doc, halt) = zetafill_cli::cmd::fill::compute(&run).unwrap_or_else(|e| panic!("{}: {e}", scene.name));
        assert!(halt.is_none());
        let bytes = zetafill_cli::cmd::fill::render(&doc, zetafill_cli::plan::format::Format::Json, &draw).unwrap_or_default();
        let v: serde_json::Value = serde_json::from_slice(&bytes).unwrap_or_default();
        let (_, _, core) = run_scene(scene, 0);
        let shapes = v["shapes"].as_array().cloned().unwrap_or_default();
        assert_eq!(shapes.len(), core.len(), "{}", scene.name);
        for (s, p) in shapes.iter().zip(&core) {
            let x = s["center"][0].as_f64().unwrap_or(f64::NAN);
            let y = s["center"][1].as_f64().unwrap_or(f64::NAN);
            assert_eq!(x.to_bits(), p.x.to_bits(), "{}", scene.name);
            assert_eq!(y.to_bits(), p.y.to_bits(), "{}", scene.name);
            if let Some(angle) = s.get("angle").and_then(|a| a.as_f64()) {
                assert_eq!(angle.to_bits(), p.angle.to_bits());
            }
        }
        let digest = zetafill_cli::cmd::fill::render(&doc, zetafill_cli::plan::format::Format::Digest, &draw).unwrap_or_default();
        let (n, h, _) = run_scene(scene, 0);
        assert_eq!(String::from_utf8_lossy(&digest), format!("{n} {h:016x}\n"));
    }
}

/// `--scalar fixed --format digest` is the digest of the core's own fixed-point engine on the
/// same scene (the value the firmware prints for `circles-fixed`), and differs from f64's.
#[test]
fn fixed_point_digest_matches_the_core() {
    use zetafill::{index_words, Engine, Fixed, Params, Placed, Region, Stop, Storage};
    let scene = &CANONICAL[0];
    let mut args = scene_args(scene);
    args.extend(["--scalar".into(), "fixed".into(), "-o".into(), "-".into()]);
    let a = parse_fill(&args);
    let (run, draw) =
        zetafill_cli::plan::fill::resolve_as(&a, zetafill_cli::plan::format::Format::Digest).unwrap_or_else(|e| panic!("{e}"));
    let (doc, _) = zetafill_cli::cmd::fill::compute(&run).unwrap_or_else(|e| panic!("{e}"));
    let line = zetafill_cli::cmd::fill::render(&doc, zetafill_cli::plan::format::Format::Digest, &draw).unwrap_or_default();
    let cap = scene.count as usize;
    let mut shapes = vec![Placed::<Fixed>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    let params = Params {
        c: scene.c,
        n_offset: scene.n,
        shape: scene.shape.into(),
        rotate: scene.rotate,
        gap: 0.0,
        max_trials: 10_000_000,
    };
    let region = Region::Rect {
        width: scene.size.0,
        height: scene.size.1,
        periodic: scene.periodic,
    };
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let mut e = Engine::<Fixed>::new(params, region, storage).unwrap_or_else(|e| panic!("{e}"));
    let mut rng = zetafill::rng_from_seed(scene.seed);
    let _ = e.run(
        &mut rng,
        &Stop {
            count: Some(scene.count),
            ..Stop::default()
        },
        |_| {},
    );
    let (n, h) = zetafill::digest::engine_digest(&e);
    assert_eq!(String::from_utf8_lossy(&line), format!("{n} {h:016x}\n"));
    let (_, h64, _) = run_scene(scene, 0);
    assert_ne!(h, h64, "fixed point and f64 give different shapes");
}

/// The flags a firmware scene's command shares with every other: rotation, power law, gap,
/// seed, count, scalar, and a digest on standard output.
fn run_flags(rotate: bool, c: f64, n: f64, gap: f64, seed: u64, count: u64, scalar: zetafill_display::ScalarKind) -> Vec<String> {
    let scalar = match scalar {
        zetafill_display::ScalarKind::F64 => "f64",
        zetafill_display::ScalarKind::Fixed => "fixed",
    };
    let rotate = if rotate { "random" } else { "none" };
    [
        ("--rotate", rotate.to_string()),
        ("--c", c.to_string()),
        ("--n-offset", n.to_string()),
        ("--gap", gap.to_string()),
        ("--seed", seed.to_string()),
        ("--count", count.to_string()),
        ("--scalar", scalar.to_string()),
        ("--format", "digest".to_string()),
        ("-o", "-".to_string()),
    ]
    .into_iter()
    .flat_map(|(flag, v)| [flag.to_string(), v])
    .collect()
}

/// The `zetafill space` arguments of a firmware 3D scene (every scene is expressible: box or
/// ball, periodic, mixes in turn, rotation, gap, scalar).
fn space_args(s: &zetafill_display::SpaceScene) -> Vec<String> {
    use zetafill::space::Region as SpaceRegion;
    let names: Vec<String> = s.solids.iter().map(zetafill_cli::args::space::solid_name).collect();
    let shape = if names.len() == 1 {
        names[0].clone()
    } else {
        format!("mix:{}", names.join(","))
    };
    let (region, periodic) = match s.region {
        SpaceRegion::Box {
            width,
            height,
            depth,
            periodic,
        } => (format!("box:{width}:{height}:{depth}"), periodic),
        SpaceRegion::Ball { radius } => (format!("ball:{radius}"), false),
        SpaceRegion::BoxMinusBall { .. } => panic!("{}: the CLI centres the removed ball; no scene uses one", s.name),
    };
    // The board runs the paper's sampler.
    let mut a: Vec<String> = [
        "zetafill",
        "space",
        "-q",
        "--sampler",
        "reference",
        "--shape",
        &shape,
        "--region",
        &region,
    ]
    .map(String::from)
    .to_vec();
    if periodic {
        a.push("--periodic".into());
    }
    a.extend(run_flags(s.rotate, s.c, s.n_offset, s.gap, s.seed, s.count, s.scalar));
    a
}

/// `zetafill space ... --format digest` prints, for every 3D scene of the firmware, the digest
/// the core gives on the host (which `tests/tests/firmware.rs` shows the Cortex-M3 prints too).
#[test]
fn space_digest_matches_the_firmware_scenes() {
    use clap::Parser;
    use zetafill::space::{Placed as PlacedSolid, Storage as SpaceStorage};
    use zetafill::{Fixed, Scalar};
    use zetafill_cli::plan::format::SpaceFormat;
    use zetafill_display::space::{run_space, SpaceScene, SPACE_CAPACITY, SPACE_INDEX_WORDS, SPACE_SCENES};
    fn core<S: Scalar + Default>(s: &SpaceScene) -> (u64, u64) {
        let mut solids = vec![PlacedSolid::<S>::default(); SPACE_CAPACITY];
        let mut index = vec![0u32; SPACE_INDEX_WORDS];
        let storage = SpaceStorage {
            solids: &mut solids,
            index: &mut index,
        };
        let o = run_space(s, storage, || 0).unwrap_or_else(|e| panic!("{}: {e}", s.name));
        (o.count, o.digest)
    }
    for s in SPACE_SCENES {
        let args = space_args(s);
        let zetafill_cli::Command::Space(a) = zetafill_cli::Cli::try_parse_from(&args)
            .unwrap_or_else(|e| panic!("{args:?}: {e}"))
            .command
        else {
            panic!("not a space command")
        };
        let (run, draw) = zetafill_cli::plan::space::resolve_as(&a, SpaceFormat::Digest).unwrap_or_else(|e| panic!("{}: {e}", s.name));
        let (doc, halt) = zetafill_cli::cmd::space::compute(&run).unwrap_or_else(|e| panic!("{}: {e}", s.name));
        assert!(halt.is_none(), "{}", s.name);
        let line = zetafill_cli::cmd::space::render(&doc, SpaceFormat::Digest, &draw).unwrap_or_default();
        let (n, h) = match s.scalar {
            zetafill_display::ScalarKind::F64 => core::<f64>(s),
            zetafill_display::ScalarKind::Fixed => core::<Fixed>(s),
        };
        assert_eq!(
            String::from_utf8_lossy(&line),
            format!("{n} {h:016x}\n"),
            "{}: {}",
            s.name,
            args.join(" ")
        );
    }
}

/// The `zetafill fill` arguments of a firmware 2D scene: every region, mix, scalar and
/// sampler of the board is expressible, and a cell-sampler scene lends the board's cells.
fn fill_args(s: &zetafill_display::Scene) -> Vec<String> {
    use zetafill_display::scenes::{SceneRegion, FAST_CELLS, SCENE_BATCH};
    let names: Vec<String> = s.shapes.iter().map(zetafill_cli::model::doc::shape_name).collect();
    let shape = if names.len() == 1 {
        names[0].clone()
    } else {
        format!("mix:{}", names.join(","))
    };
    let region = |r: String| vec!["--region".to_string(), r];
    let (place, periodic) = match s.region {
        SceneRegion::Rect(w, h, periodic) => (region(format!("rect:{w}:{h}")), periodic),
        SceneRegion::Circle(r) => (region(format!("circle:{r}")), false),
        SceneRegion::Annulus(o, i) => (region(format!("annulus:{o}:{i}")), false),
        SceneRegion::Polygon(points, ends) => {
            let mut rings = Vec::new();
            let mut start = 0;
            for &end in ends {
                let ring: Vec<String> = points[start..end].iter().map(|p| format!("{},{}", p.x, p.y)).collect();
                rings.push(ring.join(","));
                start = end;
            }
            (region(format!("polygon:{}", rings.join("/"))), false)
        }
        // A wallpaper scene's place is its group and lattice.
        SceneRegion::Wallpaper(g, a, b, angle) => {
            let lattice = match g.lattice().arity() {
                1 => format!("{a}"),
                2 => format!("{a}:{b}"),
                _ => format!("{a}:{b}:{angle}"),
            };
            (vec!["--symmetry".into(), g.name().into(), "--lattice".into(), lattice], false)
        }
    };
    let mut a: Vec<String> = ["zetafill", "fill", "-q", "--shape", &shape].map(String::from).to_vec();
    a.extend(place);
    if periodic {
        a.push("--periodic".into());
    }
    if s.batched {
        // Two threads on the host, one core on the board: the same bits.
        a.extend(
            [
                "--sampler",
                "batched",
                "--threads",
                "2",
                "--batch",
                &SCENE_BATCH.to_string(),
                "--cells",
                &FAST_CELLS.to_string(),
            ]
            .map(String::from),
        );
    } else if s.fast {
        a.extend(["--sampler".into(), "fast".into(), "--cells".into(), FAST_CELLS.to_string()]);
    } else {
        a.extend(["--sampler".into(), "reference".into()]);
    }
    a.extend(run_flags(s.rotate, s.c, s.n_offset, s.gap, s.seed, s.count, s.scalar));
    a
}

/// The digest the core gives for a firmware 2D scene on the board's storage (what
/// `tests/tests/firmware.rs` shows the Cortex-M3 prints).
fn board_digest<S: zetafill::Scalar + Default>(s: &zetafill_display::Scene) -> (u64, u64) {
    use zetafill::{Placed, Storage};
    use zetafill_display::scenes::{run, run_fast, CAPACITY, FAST_CELLS, INDEX_WORDS};
    let mut shapes = vec![Placed::<S>::default(); CAPACITY];
    let mut index = vec![0u32; INDEX_WORDS];
    let mut cells = vec![[0u64; 4]; FAST_CELLS];
    let mut frame = zetafill_display::draw::Frame::new();
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let o = if s.fast {
        run_fast(s, storage, &mut cells, &mut frame, || 0)
    } else {
        run(s, storage, &mut frame, || 0)
    }
    .unwrap_or_else(|e| panic!("{}: {e}", s.name));
    (o.count, o.digest)
}

/// `zetafill fill ... --format digest` prints, for every 2D scene of the firmware, the digest
/// the core gives on the board's storage: the cell-sampler scenes through `--cells 512`.
#[test]
fn fill_digest_matches_every_firmware_scene() {
    use zetafill_display::scenes::SCENES;
    let mut bad = Vec::new();
    for s in SCENES {
        let args = fill_args(s);
        let a = parse_fill(&args);
        let format = zetafill_cli::plan::format::Format::Digest;
        let (run, draw) = zetafill_cli::plan::fill::resolve_as(&a, format).unwrap_or_else(|e| panic!("{}: {e}", s.name));
        let (doc, halt) = zetafill_cli::cmd::fill::compute(&run).unwrap_or_else(|e| panic!("{}: {e}", s.name));
        assert!(halt.is_none(), "{}", s.name);
        let line = zetafill_cli::cmd::fill::render(&doc, format, &draw).unwrap_or_default();
        let (n, h) = match s.scalar {
            zetafill_display::ScalarKind::F64 => board_digest::<f64>(s),
            zetafill_display::ScalarKind::Fixed => board_digest::<zetafill::Fixed>(s),
        };
        if String::from_utf8_lossy(&line) != format!("{n} {h:016x}\n") {
            bad.push(format!(
                "{}: CLI {} board {n} {h:016x}: {}",
                s.name,
                String::from_utf8_lossy(&line).trim(),
                args.join(" ")
            ));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    // Without the board's cells, the cell sampler places other shapes: the flag matters.
    let s = SCENES.iter().find(|s| s.name == "circles-cells").expect("circles-cells");
    let mut args = fill_args(s);
    let at = args.iter().position(|a| a == "--cells").expect("--cells");
    args.drain(at..at + 2);
    let a = parse_fill(&args);
    let format = zetafill_cli::plan::format::Format::Digest;
    let (run, draw) = zetafill_cli::plan::fill::resolve_as(&a, format).expect("resolves");
    let (doc, _) = zetafill_cli::cmd::fill::compute(&run).expect("runs");
    let line = zetafill_cli::cmd::fill::render(&doc, format, &draw).unwrap_or_default();
    assert_ne!(
        String::from_utf8_lossy(&line),
        format!("{} {:016x}\n", board_digest::<f64>(s).0, board_digest::<f64>(s).1)
    );
}
