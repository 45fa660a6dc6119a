//! Fuzz targets of the command line's input parsers, with proptest as the engine (libFuzzer
//! needs a nightly toolchain). Each target takes arbitrary input and structured near-valid
//! input with extreme numbers, and must never panic; what it accepts must be usable:
//! - `--shape` and `--region` specs (`args::spec`): an accepted shape is valid for the core
//!   and its name reads back as the same shape; an accepted region builds a core region that
//!   places shapes, or is refused with a message naming the flag, and the `--region` text the
//!   JSON writes for it reads back as the same region;
//! - SVG outlines (`--region svg:FILE`, `io::svgin`): arbitrary bytes, mutated documents, and
//!   documents of random paths (closed, open, crossing, with holes, under transforms) give
//!   rings that `PolygonRegion::new` accepts or refuses with an error value; plain polygons
//!   read back where they were drawn;
//! - machine profiles (`output::machine`): arbitrary text and mutations of the built-ins;
//!   every profile accepted writes G-code for a small fill that passes the safety invariants
//!   (`common/safety.rs`, the replay of `gcode.rs`).
//!
//! `ZETAFILL_FUZZ_CASES` sets the number of cases of each test (default: a few hundred to a
//! few thousand, a few seconds in release mode); `ZETAFILL_FUZZ_SEED` changes the seed
//! (default fixed). A failure is shrunk, then its seed is kept in
//! `cli/proptest-regressions/fuzz/` and tried first on later runs. See docs/testing.md.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::safety::{profile_from_toml, replay};
use proptest::prelude::*;
use proptest::sample::select;
use proptest::test_runner::{Config, FileFailurePersistence, RngSeed, TestCaseError, TestRunner};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use zetafill::{index_words, rng_from_seed, CellSampler, Engine, Params, Placed, PolygonRegion, Region, Stop, Storage};
use zetafill_cli::args::spec;
use zetafill_cli::cmd::fill::region::RegionData;
use zetafill_cli::model::region::RegionSpec;

// ---------------------------------------------------------------------------------------------
// The runner

/// The number of cases of a test: `ZETAFILL_FUZZ_CASES`, or `default`.
fn cases(default: u32) -> u32 {
    std::env::var("ZETAFILL_FUZZ_CASES")
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(default)
}

/// The runner of the test `name`: its cases, the seed, and its own regression file.
fn runner(name: &str, default_cases: u32) -> TestRunner {
    let seed = std::env::var("ZETAFILL_FUZZ_SEED")
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(0x5eed_f022);
    let file: &'static str = Box::leak(format!("{}/proptest-regressions/fuzz/{name}.txt", env!("CARGO_MANIFEST_DIR")).into_boxed_str());
    TestRunner::new(Config {
        cases: cases(default_cases),
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(file))),
        rng_seed: RngSeed::Fixed(seed),
        max_shrink_iters: 4096,
        ..Config::default()
    })
}

/// Runs `test` on the values of `strategy`, panicking with the shrunk failure.
fn fuzz<S: Strategy>(name: &str, default_cases: u32, strategy: S, test: impl Fn(S::Value) -> Result<(), String>) {
    let result = runner(name, default_cases).run(&strategy, |v| test(v).map_err(TestCaseError::fail));
    if let Err(e) = result {
        panic!("{name}: {e}");
    }
}

/// Counters of what the cases did, printed at the end of a test (with `--nocapture`) and
/// checked, so that a generator that drifts into refused inputs is noticed.
#[derive(Default)]
struct Tally(Vec<(&'static str, AtomicU64)>);

impl Tally {
    fn new(names: &[&'static str]) -> Tally {
        Tally(names.iter().map(|n| (*n, AtomicU64::new(0))).collect())
    }
    fn add(&self, name: &str) {
        if let Some((_, c)) = self.0.iter().find(|(n, _)| *n == name) {
            c.fetch_add(1, Relaxed);
        }
    }
    fn get(&self, name: &str) -> u64 {
        self.0.iter().find(|(n, _)| *n == name).map_or(0, |(_, c)| c.load(Relaxed))
    }
    fn report(&self, what: &str) {
        let parts: Vec<String> = self.0.iter().map(|(n, c)| format!("{} {n}", c.load(Relaxed))).collect();
        eprintln!("{what}: {}", parts.join(", "));
    }
}

/// An error message a person can read: not empty, at most 600 bytes, no control character
/// but new lines (the hostile-input contract of `hostile.rs`).
fn readable(msg: &str) -> Result<(), String> {
    if msg.trim().is_empty() || msg.len() > 600 || msg.chars().any(|c| c.is_control() && c != '\n') {
        return Err(format!("unreadable message ({} bytes): {msg:?}", msg.len()));
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Hostile text

/// Numbers as a person, a script or an attacker writes them: plain, signed, exponents,
/// huge and tiny, not a number, with spaces, underscores, other digits, hundreds of digits.
fn number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (-1e7f64..1e7).prop_map(|v| format!("{v}")),
        2 => (0.0f64..1000.0).prop_map(|v| format!("{v:.3}")),
        1 => (0u32..100).prop_map(|v| v.to_string()),
        2 => any::<u64>().prop_map(|b| format!("{}", f64::from_bits(b))),
        1 => any::<u64>().prop_map(|b| format!("{:e}", f64::from_bits(b))),
        1 => (-400i32..400).prop_map(|e| format!("1e{e}")),
        3 => select(vec![
            "0", "-0", "+0", "0.0", "-0.0", "1", "-1", "+1", "0.5", ".5", "5.", "1e308", "1e309", "-1e309", "1e-320", "4.9e-324",
            "nan", "NaN", "-nan", "inf", "-inf", "+inf", "infinity", "Infinity", "1_000", "0x10", "1,5", " 3", "3 ", "\t3", "",
            ".", "-", "+", "e5", "1e", "1e+", "--1", "1..2", "１", "٣", "1000000", "1000000.0000000001", "999999.9999999999",
            "0.001", "0.0009999", "1000", "1000.0000001", "0.3333333333333333", "0.33333333333333337", "32", "33", "16", "17",
            "2", "3", "255", "256", "-5", "1e-300", "2.2250738585072014e-308",
        ])
        .prop_map(str::to_string),
        1 => (1usize..500).prop_map(|n| "9".repeat(n)),
        1 => (1usize..500).prop_map(|n| format!("0.{}1", "0".repeat(n))),
    ]
}

/// Any string: unicode, control characters, separators, and long runs.
fn any_text() -> impl Strategy<Value = String> {
    prop_oneof![
        3 => any::<String>(),
        3 => "[a-z:,./0-9eE+\\- ]{0,40}",
        1 => "[\\x00-\\x1f\\x7f:,/a-z0-9]{0,20}",
        1 => (any::<char>(), 1usize..3000).prop_map(|(c, n)| c.to_string().repeat(n)),
    ]
}

// ---------------------------------------------------------------------------------------------
// 1. --shape and --region

/// A spec: a name (or a near miss), a colon, and fields of hostile numbers joined by `sep`.
fn spec_text(names: &'static [&'static str], sep: &'static [&'static str]) -> impl Strategy<Value = String> {
    (
        select(names),
        prop::collection::vec(number_text(), 0..5),
        select(sep),
        prop_oneof![8 => Just(""), 1 => Just(":"), 1 => Just(" "), 1 => Just(",")],
    )
        .prop_map(|(name, fields, sep, tail)| {
            if fields.is_empty() {
                format!("{name}{tail}")
            } else {
                format!("{name}:{}{tail}", fields.join(sep))
            }
        })
}

const SHAPE_NAMES: &[&str] = &[
    "circle", "square", "triangle", "rect", "polygon", "star", "ring", "blob", "Circle", "RECT", "rect ", "hexagon", "", "mix",
];

/// A field of a spec: mostly a plausible value, else a hostile number.
fn field(plausible: impl Strategy<Value = String>) -> impl Strategy<Value = String> {
    prop_oneof![3 => plausible, 1 => number_text()]
}

/// One shape: each kind with its fields (plausible or hostile), or names and fields at random.
fn one_shape_text() -> impl Strategy<Value = String> {
    let ratio = || field((0.0f64..1.0).prop_map(|v| format!("{v}")));
    prop_oneof![
        2 => select(vec!["circle", "square", "triangle"]).prop_map(str::to_string),
        1 => field((1e-3f64..1e3).prop_map(|v| format!("{v}"))).prop_map(|a| format!("rect:{a}")),
        1 => field((0u32..40).prop_map(|v| v.to_string())).prop_map(|n| format!("polygon:{n}")),
        1 => (field((0u32..20).prop_map(|v| v.to_string())), ratio()).prop_map(|(p, r)| format!("star:{p}:{r}")),
        1 => ratio().prop_map(|r| format!("ring:{r}")),
        1 => field((0.0f64..0.4).prop_map(|v| format!("{v}"))).prop_map(|d| format!("blob:{d}")),
        2 => spec_text(SHAPE_NAMES, &[":", ":", ",", "::"]),
    ]
}

/// Shapes: one spec, or a mix of specs (sometimes more than a mix holds).
fn shape_text() -> impl Strategy<Value = String> {
    prop_oneof![
        3 => one_shape_text(),
        2 => prop::collection::vec(one_shape_text(), 0..11).prop_map(|v| format!("mix:{}", v.join(","))),
        1 => any_text(),
    ]
}

/// Regions: rect, circle, annulus with hostile numbers, and polygons of rings of random and
/// of well-formed (star, square with a hole) outlines.
fn region_text() -> impl Strategy<Value = String> {
    let size = || field(prop_oneof![3 => (0.01f64..1e4).prop_map(|v| format!("{v}")), 1 => (0u32..2000).prop_map(|v| v.to_string())]);
    let simple = prop_oneof![
        2 => (size(), size()).prop_map(|(w, h)| format!("rect:{w}:{h}")),
        1 => size().prop_map(|r| format!("circle:{r}")),
        1 => (size(), size()).prop_map(|(o, i)| format!("annulus:{o}:{i}")),
        2 => spec_text(&["rect", "circle", "annulus", "Rect", "disc", "svg-", ""], &[":", ":", ",", "::"]),
    ];
    let ring = prop::collection::vec(number_text(), 0..14).prop_map(|v| v.join(","));
    let good_ring = (3usize..20, 0.1f64..1e6, -1e5f64..1e5, any::<bool>()).prop_map(|(n, r, off, cw)| {
        let mut pts: Vec<String> = (0..n)
            .map(|k| {
                let t = k as f64 / n as f64 * std::f64::consts::TAU;
                let rr = if k % 2 == 0 { r } else { r * 0.4 };
                format!("{},{}", off + rr * t.cos(), off + rr * t.sin())
            })
            .collect();
        if cw {
            pts.reverse();
        }
        pts.join(",")
    });
    prop_oneof![
        3 => simple,
        2 => prop::collection::vec(ring, 1..4).prop_map(|r| format!("polygon:{}", r.join("/"))),
        3 => prop::collection::vec(good_ring, 1..4).prop_map(|r| format!("polygon:{}", r.join("/"))),
        1 => (1e-3f64..1e6, 0.01f64..0.99, any::<bool>()).prop_map(|(s, h, close)| {
            let (a, b) = (s * (0.5 - h / 2.0), s * (0.5 + h / 2.0));
            let first = if close { ",0,0" } else { "" };
            format!("polygon:0,0,{s},0,{s},{s},0,{s}{first}/{a},{a},{b},{a},{b},{b},{a},{b}")
        }),
        1 => any_text(),
    ]
}

/// `zetafill fill ARGS --count 5` (and `--periodic`) as the run makes it, in process: a
/// document, or a readable message that names a flag.
fn small_fill(args: &[&str], periodic: bool) -> Result<(), String> {
    let mut all = vec!["zetafill", "fill", "-q", "--count", "5", "--max-trials", "2000", "-o", "fuzz.json"];
    all.extend_from_slice(args);
    if periodic {
        all.push("--periodic");
    }
    let cli = <zetafill_cli::Cli as clap::Parser>::try_parse_from(&all).map_err(|e| format!("{all:?}: refused by clap: {e}"))?;
    let zetafill_cli::Command::Fill(a) = cli.command else {
        return Err("not a fill".into());
    };
    let done = zetafill_cli::plan::fill::resolve_as(&a, zetafill_cli::plan::format::Format::Json)
        .and_then(|(run, _)| zetafill_cli::cmd::fill::compute(&run));
    if let Err(e) = done {
        let msg = e.to_string();
        readable(&msg)?;
        if !msg.starts_with("--") {
            return Err(format!("{all:?}: refused without naming a flag: {msg}"));
        }
    }
    Ok(())
}

/// A few circles in the region with both samplers: the core takes it and never panics.
fn places_shapes(region: Region<'_>) -> Result<(), String> {
    for fast in [false, true] {
        let mut shapes = vec![Placed::<f64>::default(); 5];
        let mut index = vec![0u32; index_words(5)];
        let storage = Storage {
            shapes: &mut shapes,
            index: &mut index,
            coverage: &mut [],
        };
        let params = Params {
            max_trials: 2000,
            ..Params::circles(1.3, 1.0)
        };
        let mut e = Engine::<f64>::new(params, region, storage).map_err(|err| format!("the core refuses the region: {err}"))?;
        let stop = Stop {
            count: Some(5),
            ..Stop::default()
        };
        let mut rng = rng_from_seed(1);
        if fast {
            let mut pool = vec![[0u64; 4]; zetafill::cells_for(5)];
            let mut cells = CellSampler::new(&mut pool).map_err(|err| err.to_string())?;
            e.run_fast(&mut cells, &mut rng, &stop, |_| {});
        } else {
            e.run(&mut rng, &stop, |_| {});
        }
    }
    Ok(())
}

/// An accepted region spec is usable: it builds a core region that places shapes (or a
/// message naming the flag), and reads back from the `--region` text the JSON gives it.
fn region_usable(text: &str, spec: &RegionSpec, tally: &Tally) -> Result<(), String> {
    if let RegionSpec::Svg(_) = spec {
        // The file is read by the run (target 2); the name is not opened here.
        tally.add("svg names");
        return Ok(());
    }
    let data = RegionData::load(spec).map_err(|e| format!("{text:?}: load: {e}"))?;
    let (mut scratch, mut scratch2) = (Vec::new(), Vec::new());
    for periodic in [false, true] {
        match data.region(periodic, &mut scratch) {
            Ok(region) => {
                if !region.is_valid() {
                    return Err(format!("{text:?}: accepted as {region:?}, which the core calls invalid"));
                }
                if !(region.area().is_normal() && region.area() > 0.0) {
                    return Err(format!(
                        "{text:?}: accepted with an area of {:e}, which no size can be computed from",
                        region.area()
                    ));
                }
                places_shapes(region).map_err(|e| format!("{text:?}: {e}"))?;
                small_fill(&["--region", text], periodic).map_err(|e| format!("{text:?}: {e}"))?;
                // The --region text written in the JSON gives the same region, bit for bit.
                let doc = data.doc(&region);
                let again = spec::region(&doc.arg()).map_err(|e| format!("{text:?}: its JSON form {:?} is refused: {e}", doc.arg()))?;
                let data2 = RegionData::load(&again).map_err(|e| e.to_string())?;
                let region2 = data2
                    .region(periodic, &mut scratch2)
                    .map_err(|e| format!("{text:?}: its JSON form is refused: {e}"))?;
                let doc2 = data2.doc(&region2);
                if format!("{doc:?}") != format!("{doc2:?}") || doc.arg() != doc2.arg() {
                    return Err(format!("{text:?}: reads back as {doc2:?}, not {doc:?}"));
                }
                tally.add(if periodic { "periodic regions" } else { "regions" });
            }
            Err(e) => {
                let msg = e.to_string();
                readable(&msg)?;
                let flag = if periodic { "--periodic" } else { "--region" };
                if !(msg.starts_with("--region") || msg.starts_with(flag)) {
                    return Err(format!("{text:?}: refused by the run without naming the flag: {msg}"));
                }
                tally.add("refused by the run");
            }
        }
    }
    Ok(())
}

fn check_region_text(text: &str, tally: &Tally) -> Result<(), String> {
    match spec::region(text) {
        Ok(s) => region_usable(text, &s, tally),
        Err(msg) => {
            tally.add("refused by the parser");
            if msg.trim().is_empty() {
                return Err(format!("{text:?}: refused without a message"));
            }
            Ok(())
        }
    }
}

#[test]
fn fuzz_region_specs() {
    let tally = Tally::new(&[
        "regions",
        "periodic regions",
        "refused by the run",
        "refused by the parser",
        "svg names",
    ]);
    fuzz("region_specs", 3000, region_text(), |t| check_region_text(&t, &tally));
    tally.report("region specs");
    assert!(
        tally.get("regions") * 10 >= cases(3000) as u64,
        "fewer than one spec in ten accepted"
    );
}

fn check_shape_text(text: &str, tally: &Tally) -> Result<(), String> {
    let arg = match spec::shape(text) {
        Ok(a) => a,
        Err(msg) => {
            tally.add("refused");
            return if msg.trim().is_empty() {
                Err(format!("{text:?}: refused without a message"))
            } else {
                Ok(())
            };
        }
    };
    let list = arg.list(zetafill::MixOrder::Cycle, 7);
    if arg.0.is_empty() || arg.0.len() > zetafill::MAX_MIX || !list.is_valid() || list.kinds() != arg.0.as_slice() {
        return Err(format!("{text:?}: accepted as {arg:?}, which the core calls invalid"));
    }
    // The name (as the JSON and the command in an SVG's <desc> write it) reads back the same.
    let again = spec::shape(&arg.name()).map_err(|e| format!("{text:?}: its name {:?} is refused: {e}", arg.name()))?;
    if format!("{again:?}") != format!("{arg:?}") {
        return Err(format!("{text:?}: its name {:?} reads back as {again:?}, not {arg:?}", arg.name()));
    }
    // The core takes the shapes and places them.
    for fast in [false, true] {
        let mut shapes = vec![Placed::<f64>::default(); 5];
        let mut index = vec![0u32; index_words(5)];
        let storage = Storage {
            shapes: &mut shapes,
            index: &mut index,
            coverage: &mut [],
        };
        let params = Params {
            shape: list.clone(),
            rotate: arg.rotates(),
            max_trials: 2000,
            ..Params::circles(1.3, 20.0)
        };
        let region = Region::Rect {
            width: 100.0,
            height: 80.0,
            periodic: fast,
        };
        let mut e = Engine::<f64>::new(params, region, storage).map_err(|err| format!("{text:?}: the core refuses it: {err}"))?;
        let mut rng = rng_from_seed(3);
        let stop = Stop {
            count: Some(5),
            ..Stop::default()
        };
        if fast {
            let mut pool = vec![[0u64; 4]; zetafill::cells_for(5)];
            let mut cells = CellSampler::new(&mut pool).map_err(|err| err.to_string())?;
            e.run_fast(&mut cells, &mut rng, &stop, |_| {});
        } else {
            e.run(&mut rng, &stop, |_| {});
        }
    }
    tally.add("accepted");
    Ok(())
}

#[test]
fn fuzz_shape_specs() {
    let tally = Tally::new(&["accepted", "refused"]);
    fuzz("shape_specs", 3000, shape_text(), |t| check_shape_text(&t, &tally));
    tally.report("shape specs");
    assert!(
        tally.get("accepted") * 10 >= cases(3000) as u64,
        "fewer than one spec in ten accepted"
    );
}

/// The number parsers every flag shares: what they accept lies in their range.
#[test]
fn fuzz_number_parsers() {
    type Parser = (&'static str, fn(&str) -> Result<f64, String>, fn(f64) -> bool);
    let parsers: [Parser; 9] = [
        ("finite", spec::finite, f64::is_finite),
        ("positive", spec::positive, |v| v.is_finite() && v > 0.0),
        ("length", spec::length, |v| v > 0.0 && v <= spec::MAX_MM),
        ("length_or_zero", spec::length_or_zero, |v| (0.0..=spec::MAX_MM).contains(&v)),
        ("n_offset", spec::n_offset, |v| v > 0.0 && v <= spec::MAX_N_OFFSET),
        ("non_negative", spec::non_negative, |v| v.is_finite() && v >= 0.0),
        ("exponent", spec::exponent, |v| v.is_finite() && v > 1.0),
        ("dimension", spec::dimension, |v| v > 0.0 && v < 2.0),
        ("fraction", spec::fraction, |v| v > 0.0 && v < 1.0),
    ];
    let text = prop_oneof![4 => number_text(), 1 => any_text()];
    fuzz("number_parsers", 3000, text, |t| {
        for (name, parse, ok) in parsers {
            match parse(&t) {
                Ok(v) if !ok(v) => return Err(format!("{name}({t:?}) accepted {v}, out of its range")),
                Ok(_) => {}
                Err(m) if m.trim().is_empty() => return Err(format!("{name}({t:?}) refused without a message")),
                Err(_) => {}
            }
        }
        Ok(())
    });
}

// ---------------------------------------------------------------------------------------------
// 2. SVG outlines

/// A folder for the test's files, and a file in it for each case.
struct Scratch(tempfile::TempDir);

impl Scratch {
    fn new() -> Scratch {
        Scratch(common::tmp())
    }
    fn write(&self, name: &str, bytes: &[u8]) -> std::path::PathBuf {
        let p = self.0.path().join(name);
        std::fs::write(&p, bytes).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
        p
    }
}

/// Numbers for SVG attributes: plain, extreme, negative, with units.
fn svg_number() -> impl Strategy<Value = String> {
    prop_oneof![
        16 => (-500.0f64..500.0).prop_map(|v| format!("{v:.2}")),
        2 => (0u32..200).prop_map(|v| v.to_string()),
        1 => select(vec!["0", "-0", "1e30", "-1e30", "1e-30", "3.4e38", "1e39", "NaN", "inf", ".5", "1e", "--1", "5e-324", "1e308"])
            .prop_map(str::to_string),
    ]
}

fn svg_length() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => ((1.0f64..600.0), select(vec!["", "mm", "mm", "cm", "in", "px", "pt"])).prop_map(|(n, u)| format!("{n:.1}{u}")),
        1 => (svg_number(), select(vec!["", "mm", "pc", "%", "em", "q", "furlong"])).prop_map(|(n, u)| format!("{n}{u}")),
    ]
}

fn transform() -> impl Strategy<Value = String> {
    let n = || svg_number();
    let one = prop_oneof![
        (n(), n()).prop_map(|(a, b)| format!("translate({a},{b})")),
        n().prop_map(|a| format!("scale({a})")),
        (n(), n()).prop_map(|(a, b)| format!("scale({a} {b})")),
        n().prop_map(|a| format!("rotate({a})")),
        (n(), n(), n()).prop_map(|(a, b, c)| format!("rotate({a},{b},{c})")),
        n().prop_map(|a| format!("skewX({a})")),
        n().prop_map(|a| format!("skewY({a})")),
        prop::collection::vec(n(), 6).prop_map(|v| format!("matrix({})", v.join(","))),
        Just("matrix(0,0,0,0,0,0)".to_string()),
        Just("scale(0)".to_string()),
    ];
    prop::collection::vec(one, 1..3).prop_map(|v| v.join(" "))
}

/// Path data: subpaths of every command, absolute and relative, closed or open.
fn path_data() -> impl Strategy<Value = String> {
    let n = || svg_number();
    let cmd = prop_oneof![
        4 => (select(vec!["L", "l", "M", "m", "T", "t"]), n(), n()).prop_map(|(c, x, y)| format!("{c}{x},{y}")),
        1 => (select(vec!["H", "h", "V", "v"]), n()).prop_map(|(c, x)| format!("{c}{x}")),
        1 => (select(vec!["C", "c"]), prop::collection::vec(n(), 6)).prop_map(|(c, v)| format!("{c}{}", v.join(" "))),
        1 => (select(vec!["Q", "q", "S", "s"]), prop::collection::vec(n(), 4)).prop_map(|(c, v)| format!("{c}{}", v.join(" "))),
        1 => (select(vec!["A", "a"]), n(), n(), n(), any::<bool>(), any::<bool>(), n(), n())
            .prop_map(|(c, rx, ry, t, l, s, x, y)| format!("{c}{rx} {ry} {t} {} {} {x} {y}", u8::from(l), u8::from(s))),
        2 => Just("Z".to_string()),
    ];
    let sub = (n(), n(), prop::collection::vec(cmd, 0..12), 0u8..4).prop_map(|(x, y, cmds, close)| {
        let end = match close {
            0 => "",
            1 => " z",
            _ => " Z",
        };
        format!("M{x},{y} {}{end}", cmds.join(" "))
    });
    prop_oneof![
        6 => prop::collection::vec(sub, 1..4).prop_map(|v| v.join(" ")),
        1 => any_text(),
    ]
}

/// A star (with a hole, as a second subpath) as path data: a closed outline that is simple.
fn star_path() -> impl Strategy<Value = String> {
    (3usize..12, 5.0f64..90.0, 0.2f64..0.9, any::<bool>()).prop_map(|(n, r, inner, hole)| {
        let pt = |k: usize, rr: f64| {
            let t = k as f64 / (2 * n) as f64 * std::f64::consts::TAU;
            format!("{:.3},{:.3}", 100.0 + rr * t.cos(), 100.0 + rr * t.sin())
        };
        let mut d = format!("M{}", pt(0, r));
        for k in 1..2 * n {
            d.push_str(&format!(" L{}", pt(k, if k % 2 == 0 { r } else { r * inner })));
        }
        d.push_str(" Z");
        if hole {
            let h = r * inner * 0.5;
            d.push_str(&format!(" M{} L{} L{} Z", pt(0, h), pt(n * 2 / 3, h), pt(n * 4 / 3, h)));
        }
        d
    })
}

/// An element: a path, a basic shape, or a group (with a transform) of elements.
fn element() -> impl Strategy<Value = String> {
    let n = || svg_number();
    let attrs = || {
        (
            prop::option::of(transform()),
            select(vec![
                "",
                "fill=\"none\"",
                "fill=\"black\"",
                "stroke=\"red\"",
                "fill-rule=\"evenodd\"",
                "visibility=\"hidden\"",
                "display=\"none\"",
            ]),
        )
            .prop_map(|(t, a)| format!("{} {a}", t.map(|t| format!("transform=\"{t}\"")).unwrap_or_default()))
    };
    let leaf = prop_oneof![
        4 => (path_data(), attrs()).prop_map(|(d, a)| format!("<path d=\"{d}\" {a}/>")),
        6 => (star_path(), attrs()).prop_map(|(d, a)| format!("<path d=\"{d}\" {a}/>")),
        1 => (n(), n(), n(), n(), n(), attrs()).prop_map(|(x, y, w, h, rx, a)| format!("<rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" rx=\"{rx}\" {a}/>")),
        1 => (n(), n(), n(), attrs()).prop_map(|(x, y, r, a)| format!("<circle cx=\"{x}\" cy=\"{y}\" r=\"{r}\" {a}/>")),
        1 => (n(), n(), n(), n(), attrs()).prop_map(|(x, y, rx, ry, a)| format!("<ellipse cx=\"{x}\" cy=\"{y}\" rx=\"{rx}\" ry=\"{ry}\" {a}/>")),
        1 => (prop::collection::vec(n(), 0..12), any::<bool>(), attrs()).prop_map(|(v, poly, a)| {
            let tag = if poly { "polygon" } else { "polyline" };
            format!("<{tag} points=\"{}\" {a}/>", v.join(" "))
        }),
        1 => (n(), n(), n(), n()).prop_map(|(a, b, c, d)| format!("<line x1=\"{a}\" y1=\"{b}\" x2=\"{c}\" y2=\"{d}\"/>")),
        1 => Just("<use href=\"#p\"/>".to_string()),
        1 => Just("<text x=\"1\" y=\"1\">A</text>".to_string()),
    ];
    leaf.prop_recursive(3, 12, 4, move |inner| {
        (prop::collection::vec(inner, 0..4), prop::option::of(transform())).prop_map(|(kids, t)| {
            format!(
                "<g {}>{}</g>",
                t.map(|t| format!("transform=\"{t}\"")).unwrap_or_default(),
                kids.concat()
            )
        })
    })
}

/// A document: a root with random size and view box, and elements.
fn svg_document() -> impl Strategy<Value = String> {
    (
        prop::option::of(svg_length()),
        prop::option::of(svg_length()),
        prop::option::of(prop_oneof![
            3 => (0.0f64..50.0, 0.0f64..50.0, 10.0f64..500.0, 10.0f64..500.0).prop_map(|(x, y, w, h)| [x, y, w, h].iter().map(|v| format!("{v:.1}")).collect::<Vec<_>>()),
            1 => prop::collection::vec(svg_number(), 4),
        ]),
        prop::collection::vec(element(), 0..5),
        any::<bool>(),
    )
        .prop_map(|(w, h, vb, kids, defs)| {
            let mut root = String::from("<svg xmlns=\"http://www.w3.org/2000/svg\"");
            if let Some(w) = w {
                root.push_str(&format!(" width=\"{w}\""));
            }
            if let Some(h) = h {
                root.push_str(&format!(" height=\"{h}\""));
            }
            if let Some(vb) = vb {
                root.push_str(&format!(" viewBox=\"{}\"", vb.join(" ")));
            }
            let defs = if defs {
                "<defs><path id=\"p\" d=\"M10,10 L90,10 L50,80 Z\"/></defs>"
            } else {
                ""
            };
            format!("{root}>{defs}{}</svg>", kids.concat())
        })
}

/// Bytes of a file given as `svg:FILE`: arbitrary bytes, documents, and documents with a
/// few bytes changed.
fn svg_bytes() -> impl Strategy<Value = Vec<u8>> {
    prop_oneof![
        1 => prop::collection::vec(any::<u8>(), 0..600),
        8 => svg_document().prop_map(String::into_bytes),
        1 => (svg_document(), prop::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..6)).prop_map(|(doc, edits)| {
            let mut b = doc.into_bytes();
            for (at, byte, how) in edits {
                if b.is_empty() {
                    break;
                }
                let i = at.index(b.len());
                match how {
                    0 => b[i] = byte,
                    1 => b.insert(i, byte),
                    _ => {
                        b.remove(i);
                    }
                }
            }
            b
        }),
    ]
}

/// What an outline must be: rings of at least 3 finite points, ends increasing to the
/// number of points; then the core accepts it or refuses it with an error value, and the
/// run resolves it into a region that places shapes or a message naming `--region`.
/// Outline rings: the points, ring after ring, and the end of each ring.
type Rings = (Vec<zetafill::Point<f64>>, Vec<usize>);

fn check_outline(path: &Path, tally: &Tally) -> Result<Option<Rings>, String> {
    let (points, ends) = match zetafill_cli::io::svgin::read_outline(path) {
        Ok(o) => o,
        Err(e) => {
            let msg = zetafill_cli::plan::region::outline_error(path, e).to_string();
            readable(&msg)?;
            tally.add("no outline");
            return Ok(None);
        }
    };
    let mut start = 0;
    for &e in &ends {
        if e < start + 3 {
            return Err(format!("a ring of {} points: ends {ends:?}", e.saturating_sub(start)));
        }
        start = e;
    }
    if start != points.len() || ends.is_empty() {
        return Err(format!("ends {ends:?} for {} points", points.len()));
    }
    if let Some(p) = points.iter().find(|p| !(p.x.is_finite() && p.y.is_finite())) {
        return Err(format!("a point that is not finite: {p:?}"));
    }
    let mut tree = vec![0u32; PolygonRegion::scratch_words(points.len())];
    match PolygonRegion::new_in(&points, &ends, &mut tree) {
        Ok(_) => tally.add("polygons"),
        Err(e) => {
            let _ = e.to_string();
            tally.add("refused by the core");
        }
    }
    let data = RegionData::load(&RegionSpec::Svg(path.to_path_buf())).map_err(|e| format!("read twice, refused: {e}"))?;
    let mut scratch = Vec::new();
    match data.region(false, &mut scratch) {
        Ok(region) => places_shapes(region)?,
        Err(e) => {
            let msg = e.to_string();
            readable(&msg)?;
            if !msg.starts_with("--region") {
                return Err(format!("refused without naming --region: {msg}"));
            }
        }
    }
    Ok(Some((points, ends)))
}

#[test]
fn fuzz_svg_outlines() {
    let dir = Scratch::new();
    let tally = Tally::new(&["no outline", "polygons", "refused by the core"]);
    fuzz("svg_outlines", 1500, svg_bytes(), |bytes| {
        let path = dir.write("outline.svg", &bytes);
        check_outline(&path, &tally).map(|_| ())
    });
    tally.report("svg outlines");
    assert!(
        tally.get("polygons") * 10 >= cases(1500) as u64,
        "fewer than one file in ten gave a polygon"
    );
}

/// A polygon drawn in a 1:1 mm document (no transform) reads back where it was drawn, in
/// the region frame (y up from the bottom of the page).
#[test]
fn fuzz_svg_polygons_read_back_where_drawn() {
    let dir = Scratch::new();
    let tally = Tally::new(&["polygons"]);
    let ring = (3usize..24, 1.0f64..90.0, 0.2f64..1.0, any::<u64>(), select(vec!["path", "polygon"]));
    fuzz("svg_read_back", 500, ring, |(n, r, inner, seed, tag)| {
        let mut m = seed;
        let mut unit = || {
            m = m.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (m >> 11) as f64 / (1u64 << 53) as f64
        };
        // Star-shaped about (100, 100), vertices on a 0.01 mm grid.
        let pts: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let t = (k as f64 + 0.5 * unit()) / n as f64 * std::f64::consts::TAU;
                let rr = r * (inner + (1.0 - inner) * unit());
                [
                    ((100.0 + rr * t.cos()) * 100.0).round() / 100.0,
                    ((100.0 + rr * t.sin()) * 100.0).round() / 100.0,
                ]
            })
            .collect();
        let list: Vec<String> = pts.iter().map(|p| format!("{},{}", p[0], p[1])).collect();
        let el = if tag == "path" {
            format!("<path d=\"M{} Z\"/>", list.join(" L"))
        } else {
            format!("<polygon points=\"{}\"/>", list.join(" "))
        };
        let doc = format!("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200mm\" height=\"200mm\" viewBox=\"0 0 200 200\">{el}</svg>");
        let path = dir.write("polygon.svg", doc.as_bytes());
        let Some((points, ends)) = check_outline(&path, &tally)? else {
            return Err(format!("no outline in {doc}"));
        };
        // Repeated vertices (after rounding) are dropped.
        let mut want: Vec<[f64; 2]> = pts.iter().map(|p| [p[0], 200.0 - p[1]]).collect();
        want.dedup();
        if want.len() > 1 && want.first() == want.last() {
            want.pop();
        }
        let got: Vec<[f64; 2]> = points.iter().map(|p| [p.x, p.y]).collect();
        let close = got.len() == want.len()
            && got
                .iter()
                .zip(&want)
                .all(|(a, b)| (a[0] - b[0]).abs() < 1e-3 && (a[1] - b[1]).abs() < 1e-3);
        if ends != [got.len()] || !close {
            return Err(format!("drawn {want:?}, read {got:?} (ends {ends:?})"));
        }
        Ok(())
    });
}

// ---------------------------------------------------------------------------------------------
// 3. Machine profiles

/// G-code words and lines a profile block might hold: allowed, refused, and malformed.
fn gcode_line() -> impl Strategy<Value = String> {
    let letter = select(vec![
        'G', 'M', 'X', 'Y', 'Z', 'F', 'S', 'P', 'T', 'I', 'J', 'R', 'E', 'N', 'g', 'm', 'z', 's', 'f', 'p',
    ]);
    let value = prop_oneof![
        4 => (0u32..100).prop_map(|v| v.to_string()),
        2 => (-2000.0f64..2000.0).prop_map(|v| format!("{v:.3}")),
        1 => select(vec!["59.1", "38.2", "28.1", "92.1", "0.0", "-0", "+5", ".5", "5.", "1e3", "1E3", "nan", "inf", "1000000", "1000001", "600", "600.001", "-1000", "1000.0001", "", "{power}", "{feed}", "{travel_feed}", "{x}", "99999999999999999999"])
            .prop_map(str::to_string),
    ];
    let word = (letter, value, select(vec!["", "", " ", "\t"])).prop_map(|(l, v, s)| format!("{l}{s}{v}"));
    let valid = (
        select(vec!["G0 Z", "G1 F600 Z", "M3 S", "M4 S", "S", "G4 P", "F"]),
        (0.0f64..100.0).prop_map(|v| format!("{v:.2}")),
        select(vec!["", "", " ; note", " (note)"]),
    )
        .prop_map(|(w, v, c)| format!("{w}{v}{c}"));
    prop_oneof![
        4 => valid,
        5 => (prop::collection::vec(word, 1..4), select(vec!["", "", " ; note", " (note)", ";", "(", " ; {power}"])).prop_map(|(w, c)| format!("{}{c}", w.join(" "))),
        3 => select(vec![
            "M3 S30", "M3 S90", "M5", "M5 S0", "M4 S{power}", "M3 S{power}", "G0 Z3.000", "G1 Z0.000 F600", "G0 Z5", "G1 Z-1", "G4 P0.15", "G4 P0",
            "G4", "M0", "M1", "M2", "M30", "M6 T1", "M7", "M8", "M9", "G17", "G90", "G91", "G20", "G21", "G28", "G53 G0 Z0", "G92 X0", "G54",
            "G0 X10 Y10", "G2 X1 Y1 I1", "S0", "S1000", "F1000", "$H", "%", "#1=5", "M3 S30\r", "M3\u{1b}[31m", "é", "",
        ])
        .prop_map(str::to_string),
    ]
}

/// A TOML value for a numeric field: plain, extreme, of the wrong type.
fn toml_number() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (0.0f64..2000.0).prop_map(|v| format!("{v:.1}")),
        2 => (1u32..200_000).prop_map(|v| v.to_string()),
        1 => any::<u64>().prop_map(|b| format!("{:e}", f64::from_bits(b))).prop_filter("TOML floats", |s| !s.contains("NaN") && !s.contains("inf")),
        1 => select(vec!["0", "-0.0", "-1", "1e-300", "1e300", "1e6", "100000", "100000.0001", "nan", "inf", "-inf", "0.001", "\"300\"", "true", "[1, 2]", "{}", ""])
            .prop_map(str::to_string),
    ]
}

/// A built-in profile with a few changes: G-code lines inserted into a block, a block
/// replaced, a number changed, an enum or a key changed, a line dropped or repeated.
fn mutated_profile() -> impl Strategy<Value = String> {
    let names = zetafill_cli::output::machine::Machine::builtin_names();
    let edit = prop_oneof![
        4 => (select(vec!["start", "tool_on", "tool_off", "pen_change", "end"]), prop::collection::vec(gcode_line(), 1..4), any::<bool>())
            .prop_map(|(k, lines, replace)| Edit::Block(k, lines.join("\n"), replace)),
        3 => (select(vec!["width", "height", "draw", "travel", "min", "max", "default"]), prop_oneof![3 => (1.0f64..1000.0).prop_map(|v| format!("{v:.1}")), 1 => toml_number()]).prop_map(|(k, v)| Edit::Number(k, v)),
        1 => prop_oneof![3 => (0.0f64..300.0, 0.0f64..300.0).prop_map(|(a, b)| (format!("{a:.1}"), format!("{b:.1}"))), 1 => (toml_number(), toml_number())].prop_map(|(a, b)| Edit::Park(a, b)),
        2 => prop_oneof![
            4 => select(vec![("units", "\"mm\""), ("units", "\"inch\""), ("origin", "\"center\""), ("origin", "\"top-left\""), ("origin", "\"bottom-left\""), ("travel", "\"feed\""), ("travel", "\"rapid\""), ("arcs", "true"), ("arcs", "false")]),
            1 => (select(vec!["units", "origin", "arcs", "travel"]), select(vec!["\"left\"", "1", "\"MM\"", "\"\""])),
        ]
            .prop_map(|(k, v)| Edit::Value(k, v.to_string())),
        1 => Just(Edit::Power),
        1 => (any::<prop::sample::Index>(), 0u8..3).prop_map(|(i, how)| Edit::Line(i, how)),
    ];
    (select(names), prop::collection::vec(edit, 1..4)).prop_map(|(name, edits)| {
        let mut text = zetafill_cli::output::machine::Machine::builtin_text(name).unwrap_or("").to_string();
        for e in edits {
            text = e.apply(&text);
        }
        text
    })
}

/// One change to a profile's text.
#[derive(Clone, Debug)]
enum Edit {
    /// Lines for a block: added to its end, or in place of it (the block is added if absent).
    Block(&'static str, String, bool),
    /// A new value for every `KEY = number` line.
    Number(&'static str, String),
    /// A park position.
    Park(String, String),
    /// A new value for a `KEY = ...` line.
    Value(&'static str, String),
    /// A power range added (or removed, when there is one).
    Power,
    /// A line removed, repeated or emptied.
    Line(prop::sample::Index, u8),
}

impl Edit {
    fn apply(&self, text: &str) -> String {
        let set = |key: &str, value: &str| -> String {
            text.lines()
                .map(|l| {
                    if l.split('=').next().map(str::trim) == Some(key) && l.contains('=') && !l.contains("\"\"\"") {
                        format!("{key} = {value}")
                    } else {
                        l.to_string()
                    }
                })
                .collect::<Vec<_>>()
                .join("\n")
                + "\n"
        };
        match self {
            Edit::Block(key, lines, replace) => {
                let open = format!("{key} = \"\"\"\n");
                match text.find(&open) {
                    Some(at) => {
                        let body = at + open.len();
                        let end = text[body..].find("\"\"\"").map_or(text.len(), |e| body + e);
                        if *replace {
                            format!("{}{lines}\n{}", &text[..body], &text[end..])
                        } else {
                            format!("{}{lines}\n{}", &text[..end], &text[end..])
                        }
                    }
                    // Before the first table, where top-level keys belong.
                    None => match text.find("\n[") {
                        Some(at) => format!("{}\n{key} = \"\"\"\n{lines}\n\"\"\"{}", &text[..at], &text[at..]),
                        None => format!("{text}\n{key} = \"\"\"\n{lines}\n\"\"\"\n"),
                    },
                }
            }
            Edit::Number(key, v) => set(key, v),
            Edit::Value(key, v) => set(key, v),
            Edit::Park(a, b) => match text.lines().any(|l| l.starts_with("park")) {
                true => set("park", &format!("[{a}, {b}]")),
                false => format!("park = [{a}, {b}]\n{text}"),
            },
            Edit::Power => match text.find("\n[power]") {
                Some(at) => text[..at].to_string() + "\n",
                None => format!("{text}\n[power]\nmin = 0.0\nmax = 1000.0\ndefault = 800.0\n"),
            },
            Edit::Line(i, how) => {
                let mut lines: Vec<&str> = text.lines().collect();
                if lines.is_empty() {
                    return text.to_string();
                }
                let k = i.index(lines.len());
                match how {
                    0 => {
                        lines.remove(k);
                    }
                    1 => lines.insert(k, lines[k]),
                    _ => lines[k] = "",
                }
                lines.join("\n") + "\n"
            }
        }
    }
}

/// Profile texts: mutated built-ins mostly, TOML-like soup and arbitrary text.
fn profile_text() -> impl Strategy<Value = String> {
    let key = select(vec![
        "name",
        "description",
        "units",
        "origin",
        "arcs",
        "travel",
        "park",
        "start",
        "tool_on",
        "tool_off",
        "pen_change",
        "end",
        "width",
        "speed",
        "[bed]",
        "[feed]",
        "[power]",
    ]);
    let soup = prop::collection::vec((key, toml_number()), 0..12).prop_map(|kv| {
        kv.iter()
            .map(|(k, v)| {
                if k.starts_with('[') {
                    format!("{k}\n")
                } else {
                    format!("{k} = {v}\n")
                }
            })
            .collect::<String>()
    });
    prop_oneof![
        8 => mutated_profile(),
        1 => soup,
        1 => any_text(),
    ]
}

/// A small fill written as G-code for `machine` (a profile file) with random plot flags;
/// `Ok(None)` when the flags are refused (naming one).
fn small_fill_gcode(machine: &Path, flags: &PlotFlags) -> Result<Option<Vec<u8>>, String> {
    let mut args: Vec<String> = ["zetafill", "fill", "-q", "--machine"].iter().map(|s| s.to_string()).collect();
    args.push(machine.display().to_string());
    args.extend(flags.args());
    args.extend(["-o".to_string(), "fuzz.gcode".to_string()]);
    let cli = match <zetafill_cli::Cli as clap::Parser>::try_parse_from(&args) {
        Ok(c) => c,
        Err(e) => return Err(format!("{args:?}: the command line is refused: {e}")),
    };
    let zetafill_cli::Command::Fill(a) = cli.command else {
        return Err("not a fill".into());
    };
    let refused = |e: zetafill_cli::error::CliError| -> Result<Option<Vec<u8>>, String> {
        let msg = e.to_string();
        readable(&msg)?;
        if !msg.starts_with("--") {
            return Err(format!("{args:?}: refused without naming a flag: {msg}"));
        }
        Ok(None)
    };
    let (run, draw) = match zetafill_cli::plan::fill::resolve_as(&a, zetafill_cli::plan::format::Format::Gcode) {
        Ok(p) => p,
        Err(e) => return refused(e),
    };
    let (doc, _) = match zetafill_cli::cmd::fill::compute(&run) {
        Ok(d) => d,
        Err(e) => return refused(e),
    };
    match zetafill_cli::cmd::fill::render(&doc, zetafill_cli::plan::format::Format::Gcode, &draw) {
        Ok(bytes) => Ok(Some(bytes)),
        Err(e) => refused(e),
    }
}

/// The plot flags of a small fill.
#[derive(Clone, Debug)]
struct PlotFlags {
    region: String,
    shape: &'static str,
    count: u32,
    seed: u64,
    place: &'static str,
    extra: Vec<String>,
}

impl PlotFlags {
    /// The value of `flag`, if given.
    fn value(&self, flag: &str) -> Option<f64> {
        let at = self.extra.iter().position(|a| a == flag)?;
        self.extra.get(at + 1)?.parse().ok()
    }

    /// The `--margin` (0 when not given).
    fn margin(&self) -> f64 {
        self.value("--margin").unwrap_or(0.0)
    }

    fn args(&self) -> Vec<String> {
        let mut a: Vec<String> = vec![
            "--region".into(),
            self.region.clone(),
            "--shape".into(),
            self.shape.into(),
            "--count".into(),
            self.count.to_string(),
            "--seed".into(),
            self.seed.to_string(),
            "--n-offset".into(),
            "3".into(),
            "--max-trials".into(),
            "20000".into(),
        ];
        if !self.place.is_empty() {
            a.push(self.place.into());
        }
        a.extend(self.extra.iter().cloned());
        a
    }
}

fn plot_flags() -> impl Strategy<Value = PlotFlags> {
    // Each flag at most once, each given one time in five.
    let maybe = |s: BoxedStrategy<Vec<String>>| prop_oneof![4 => Just(vec![]), 1 => s];
    let extra = (
        maybe(Just(vec!["--no-arcs".to_string()]).boxed()),
        maybe((1u32..4).prop_map(|p| vec!["--passes".to_string(), p.to_string()]).boxed()),
        maybe(
            (0.5f64..5.0, 0u32..180)
                .prop_map(|(s, a)| vec!["--hatch".to_string(), format!("{s:.2}:{a}")])
                .boxed(),
        ),
        maybe(
            select(vec!["none", "greedy", "improved"])
                .prop_map(|o| vec!["--order".to_string(), o.to_string()])
                .boxed(),
        ),
        maybe((0.0f64..5.0).prop_map(|m| vec!["--margin".to_string(), format!("{m:.2}")]).boxed()),
        maybe(
            Just(
                ["--layers", "colours", "--palette", "000000,ff0000,00ff00", "--color-by", "random"]
                    .map(str::to_string)
                    .to_vec(),
            )
            .boxed(),
        ),
        maybe(
            (0.0f64..1000.0)
                .prop_map(|p| vec!["--power".to_string(), format!("{p:.0}")])
                .boxed(),
        ),
        maybe(
            (100.0f64..5000.0)
                .prop_map(|f| vec!["--feed".to_string(), format!("{f:.0}")])
                .boxed(),
        ),
    )
        .prop_map(|(a, b, c, d, e, f, g, h)| [a, b, c, d, e, f, g, h].concat());
    (
        prop_oneof![
            3 => (5.0f64..400.0, 5.0f64..400.0).prop_map(|(w, h)| format!("rect:{w:.1}:{h:.1}")),
            1 => (5.0f64..200.0).prop_map(|r| format!("circle:{r:.1}")),
            1 => Just("polygon:0,0,100,0,100,100,0,100/30,30,30,70,70,70,70,30".to_string()),
        ],
        select(vec!["circle", "square", "ring:0.5", "star:5:0.4", "mix:circle,triangle"]),
        5u32..40,
        any::<u64>(),
        select(vec!["--fit", "--fit", "--fit", "--center", ""]),
        extra,
    )
        .prop_map(|(region, shape, count, seed, place, extra)| PlotFlags {
            region,
            shape,
            count,
            seed,
            place,
            extra,
        })
}

fn check_profile(dir: &Scratch, text: &str, flags: &PlotFlags, tally: &Tally) -> Result<(), String> {
    use zetafill_cli::output::machine::Machine;
    let m = match Machine::parse(text) {
        Ok(m) => m,
        Err(msg) => {
            tally.add("refused");
            if msg.trim().is_empty() || msg.chars().any(|c| c.is_control()) {
                return Err(format!("refused with an unreadable message: {msg:?}"));
            }
            return Ok(());
        }
    };
    tally.add("accepted");
    let _ = m.validate();
    let path = dir.write("machine.toml", text.as_bytes());
    let Some(bytes) = small_fill_gcode(&path, flags)? else {
        tally.add("flags refused");
        return Ok(());
    };
    let program = String::from_utf8(bytes).map_err(|_| "the G-code is not UTF-8".to_string())?;
    let r = replay(&program, &profile_from_toml(text));
    if !r.errors.is_empty() {
        let show: String = program.lines().take(60).collect::<Vec<_>>().join("\n");
        return Err(format!(
            "unsafe G-code ({} faults, first {:?}) from profile\n{text}\nprogram:\n{show}",
            r.errors.len(),
            &r.errors[..r.errors.len().min(3)]
        ));
    }
    let v: toml::Value = toml::from_str(text).map_err(|e| e.to_string())?;
    // A bed (less the margin) under 1 mm has the drawing fitted to a few grid points.
    let bed = |k: &str| {
        v.get("bed")
            .and_then(|b| b.get(k))
            .and_then(|d| d.as_float().or(d.as_integer().map(|i| i as f64)))
    };
    let room = bed("width").unwrap_or(0.0).min(bed("height").unwrap_or(0.0)) - 2.0 * flags.margin();
    let draws = program.lines().any(|l| ["G1 X", "G2 X", "G3 X"].iter().any(|m| l.starts_with(m)));
    if !draws && room >= 1.0 {
        return Err(format!("nothing drawn for profile\n{text}"));
    }
    tally.add("programs");
    Ok(())
}

#[test]
fn fuzz_machine_profiles() {
    let dir = Scratch::new();
    let tally = Tally::new(&["accepted", "refused", "flags refused", "programs"]);
    fuzz("machine_profiles", 1000, (profile_text(), plot_flags()), |(text, flags)| {
        check_profile(&dir, &text, &flags, &tally)
    });
    tally.report("machine profiles");
    assert!(
        tally.get("programs") * 10 >= cases(1000) as u64,
        "fewer than one profile in ten wrote G-code"
    );
}
