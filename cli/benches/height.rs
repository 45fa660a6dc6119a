//! Height-map benchmark (a plain binary, `harness = false`): the time to render `fill
//! --relief` maps of fills from 10^3 to 10^5 shapes at 1024 and 4096 pixels a side (16
//! samples a pixel), for circles and for stars (ten edges each), with the samples per second.
//!
//! Run with `cargo bench -p zetafill-cli --bench height`. Prints a Markdown table for the
//! README. Measures only; the test suite asserts nothing about time.

use std::time::Instant;
use zetafill_cli::output::height::{grid, render, Relief};
use zetafill_cli::output::png::Raster;

fn fill(args: &[&str]) -> zetafill_cli::model::doc::FillDoc {
    let mut v = vec!["zetafill", "fill", "-q", "-o", "x.json"];
    v.extend_from_slice(args);
    let cli = <zetafill_cli::Cli as clap::Parser>::try_parse_from(&v).unwrap_or_else(|e| panic!("{e}"));
    let zetafill_cli::Command::Fill(a) = cli.command else {
        panic!("not fill")
    };
    zetafill_cli::cmd::fill::compute(
        &zetafill_cli::plan::fill::resolve_as(&a, zetafill_cli::plan::format::Format::Json)
            .unwrap_or_else(|e| panic!("{e}"))
            .0,
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .0
}

fn main() {
    println!("| shapes | n | pixels | relief | time (ms) | samples/s | PNG bytes |");
    println!("|---|---:|---:|---|---:|---:|---:|");
    let circles = |n: &str| fill(&["--count", n]);
    let stars = |n: &str| fill(&["--shape", "star:5:0.45", "--c", "1.2", "--n-offset", "3", "--count", n]);
    for (name, n, make) in [
        ("circles", "1000", &circles as &dyn Fn(&str) -> _),
        ("circles", "100000", &circles),
        ("stars", "1000", &stars),
        ("stars", "10000", &stars),
    ] {
        let doc = make(n);
        for pixels in [1024u32, 4096] {
            let raster = Raster {
                dpi: 96.0,
                pixels: Some(pixels),
            };
            let size = grid(doc.extent(), &raster).unwrap_or_else(|e| panic!("{e:?}"));
            // The fastest of three runs.
            let (mut best, mut bytes) = (f64::MAX, 0);
            for _ in 0..3 {
                let t = Instant::now();
                let png = render(&doc, Relief::Dome, size, "bench").unwrap_or_else(|e| panic!("{e}"));
                best = best.min(t.elapsed().as_secs_f64());
                bytes = png.len();
            }
            let samples = (16 * size.0 * size.1) as f64;
            println!(
                "| {name} | {n} | {pixels} | dome | {:.0} | {:.3e} | {bytes} |",
                best * 1e3,
                samples / best
            );
        }
    }
}
