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
//! - machine profiles (`output::machine`): arbitrary text and mutations of the built-ins
//!   (park positions and tables written as arrays of any length among them); every profile
//!   accepted writes G-code for a small fill that passes the safety invariants
//!   (`common/safety.rs`, the replay of `gcode.rs`) with every feed as asked, and holds no
//!   array of the wrong length; an array of the wrong length is refused naming its key's line;
//! - feeds: every built-in profile in inches or mm, any origin, travel mode and arcs, any
//!   `--feed` and `--travel-feed` from 1 to 1,000,000 mm/min: the G-code is safe and every
//!   feed read back is within 0.1 % of what was asked in inches (the whole mm/min in mm).
//!
//! - pictures (`--density image:FILE`, `--region mask:FILE`, `io::image`): arbitrary bytes
//!   behind a signature and mutated pictures of every PNG colour type and depth and JPEG
//!   decode to sound luminances or a readable error; as a density or a mask the tool exits 0,
//!   2 or 3 and a refusal names its flag.
//!
//! The targets live in `fuzz/`, one file each (`specs.rs`, `svg.rs`, `machines.rs`,
//! `feeds.rs`, `pictures.rs`), under the shared runner and generators of this file.
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

/// The targets, one file each in `fuzz/`.
mod fuzz {
    mod feeds;
    mod machines;
    mod pictures;
    mod specs;
    mod svg;
}

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
