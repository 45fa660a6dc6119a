//! Shared helpers for the workspace-level tests: running the core on a canonical scene and
//! running the CLI in process.

use zetafill::{digest, index_words, Engine, Params, Placed, Region, ShapeKind, Stop, Storage};

/// A fixed scene: parameters, region, seed and count.
#[derive(Debug, Clone, Copy)]
pub struct Scene {
    /// Name used in messages.
    pub name: &'static str,
    /// Shape.
    pub shape: ShapeKind,
    /// Random rotation.
    pub rotate: bool,
    /// Width, height.
    pub size: (f64, f64),
    /// Periodic boundary.
    pub periodic: bool,
    /// c.
    pub c: f64,
    /// N.
    pub n: f64,
    /// Seed.
    pub seed: u64,
    /// Shapes.
    pub count: u64,
}

/// The canonical scenes shared with the firmware (docs/firmware.md, What it runs).
pub const CANONICAL: [Scene; 3] = [
    Scene {
        name: "circles",
        shape: ShapeKind::Circle,
        rotate: false,
        size: (200.0, 200.0),
        periodic: false,
        c: 1.3,
        n: 1.0,
        seed: 1,
        count: 500,
    },
    Scene {
        name: "squares",
        shape: ShapeKind::Square,
        rotate: true,
        size: (100.0, 100.0),
        periodic: true,
        c: 1.25,
        n: 2.0,
        seed: 2,
        count: 300,
    },
    Scene {
        name: "rects",
        shape: ShapeKind::Rect { aspect: 2.0 },
        rotate: false,
        size: (150.0, 100.0),
        periodic: false,
        c: 1.2,
        n: 3.0,
        seed: 3,
        count: 300,
    },
];

/// Runs a scene in the core (f64) with `coverage_words` of bitmap and returns
/// (count, digest, placed shapes).
pub fn run_scene(s: &Scene, coverage_words: usize) -> (u64, u64, Vec<Placed<f64>>) {
    let cap = s.count as usize;
    let mut shapes = vec![Placed::<f64>::default(); cap];
    let mut index = vec![0u32; index_words(cap)];
    let mut coverage = vec![0u64; coverage_words];
    let params = Params {
        c: s.c,
        n_offset: s.n,
        shape: s.shape.into(),
        rotate: s.rotate,
        gap: 0.0,
        max_trials: 10_000_000,
    };
    let region = Region::Rect {
        width: s.size.0,
        height: s.size.1,
        periodic: s.periodic,
    };
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut coverage,
    };
    let Ok(mut e) = Engine::<f64>::new(params, region, storage) else {
        return (0, 0, Vec::new());
    };
    let mut rng = zetafill::rng_from_seed(s.seed);
    let _ = e.run(
        &mut rng,
        &Stop {
            count: Some(s.count),
            ..Stop::default()
        },
        |_| {},
    );
    let (n, h) = digest::engine_digest(&e);
    (n, h, e.placed().to_vec())
}

/// The `zetafill fill` arguments of a scene (without output).
pub fn scene_args(s: &Scene) -> Vec<String> {
    let shape = zetafill_cli::model::doc::shape_name(&s.shape);
    let mut v: Vec<String> = vec![
        "zetafill".into(),
        "fill".into(),
        "--shape".into(),
        shape,
        "--rotate".into(),
        if s.rotate { "random".into() } else { "none".into() },
        "--region".into(),
        format!("rect:{}:{}", s.size.0, s.size.1),
        "--c".into(),
        s.c.to_string(),
        "--n-offset".into(),
        s.n.to_string(),
        "--seed".into(),
        s.seed.to_string(),
        "--count".into(),
        s.count.to_string(),
        // The canonical digests (and the firmware's) are the reference sampler's.
        "--sampler".into(),
        "reference".into(),
    ];
    if s.periodic {
        v.push("--periodic".into());
    }
    v
}

/// Parses `zetafill fill` arguments (program name first) into the CLI's argument struct.
pub fn parse_fill(args: &[String]) -> zetafill_cli::args::fill::FillArgs {
    use clap::Parser;
    match zetafill_cli::Cli::try_parse_from(args) {
        Ok(zetafill_cli::Cli {
            command: zetafill_cli::Command::Fill(a),
        }) => a,
        Ok(_) => panic!("not a fill command: {args:?}"),
        Err(e) => panic!("bad arguments {args:?}: {e}"),
    }
}

/// The code blocks of docs/library.md, each a whole program, compiled and run as doctests: the
/// page's examples cannot fall behind the API.
#[cfg(doctest)]
#[doc = include_str!("../../docs/library.md")]
pub struct LibraryPage;
