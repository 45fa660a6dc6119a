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
