//! 3D benchmark (a plain binary, `harness = false`): a fill of 10^5 spheres at c = 1.15, N = 1
//! in a 100 mm cube (seed 1) by each sampler where it is practical (the paper's up to 10^4),
//! then the time to write it as JSON, CSV, glTF binary and binary STL (24 segments), with the
//! output sizes. Run with `cargo bench -p zetafill-cli --bench space [-- COUNT]`. Measures only;
//! the test suite asserts nothing about time.

use std::time::Instant;
use zetafill_cli::plan::format::SpaceFormat;

fn main() {
    let count = std::env::args()
        .skip(1)
        .find_map(|a| a.parse::<u64>().ok())
        .unwrap_or(100_000)
        .to_string();
    let v = [
        "zetafill", "space", "-q", "--c", "1.15", "--count", &count, "--seed", "1", "-o", "x.json",
    ];
    let cli = <zetafill_cli::Cli as clap::Parser>::try_parse_from(v).unwrap_or_else(|e| panic!("{e}"));
    let zetafill_cli::Command::Space(a) = cli.command else {
        panic!("not space")
    };
    let (run, draw) = zetafill_cli::plan::space::resolve_as(&a, SpaceFormat::Json).unwrap_or_else(|e| panic!("{e}"));
    let t = Instant::now();
    let (doc, halt) = zetafill_cli::cmd::space::compute(&run).unwrap_or_else(|e| panic!("{e}"));
    assert!(halt.is_none(), "the fill halted");
    let fill = t.elapsed().as_secs_f64();
    println!("| step | solids | time (s) | bytes |");
    println!("|---|---:|---:|---:|");
    println!("| fill (cell sampler) | {count} | {fill:.2} | - |");
    for (name, format) in [
        ("JSON", SpaceFormat::Json),
        ("CSV", SpaceFormat::Csv),
        ("GLB", SpaceFormat::Glb),
        ("STL", SpaceFormat::Stl),
    ] {
        let t = Instant::now();
        let bytes = zetafill_cli::cmd::space::render(&doc, format, &draw).unwrap_or_else(|e| panic!("{name}: {e}"));
        println!("| write {name} | {count} | {:.2} | {} |", t.elapsed().as_secs_f64(), bytes.len());
    }
}
