//! 2D writing benchmark (a plain binary, `harness = false`): one fill of circles at c = 1.3,
//! N = 1 in 200 x 200 mm (seed 1, cell sampler), then each writer timed on it, the writer the
//! tool uses beside its control (`output::control`: numbers through the standard formatter,
//! JSON through `serde_json`; both build SVG with the `svg` crate), with the output sizes. The SVG
//! times include building the drawing from the fill. Run with
//! `cargo bench -p zetafill-cli --bench writing [-- COUNT]` (default 10^5). Measures only; the
//! test suite asserts nothing about time.

use std::time::Instant;
use zetafill_cli::output::{control, csv, json, svg};
use zetafill_cli::plan::format::Format;

/// CPU seconds of this thread so far, to the nanosecond (`CLOCK_THREAD_CPUTIME_ID`), so that
/// other work on the machine does not count.
fn cpu() -> f64 {
    let t = rustix::time::clock_gettime(rustix::time::ClockId::ThreadCPUTime);
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

/// Runs `f`, returning its result and (wall, CPU) seconds.
fn timed<T>(f: impl FnOnce() -> T) -> (T, f64, f64) {
    let (t, c) = (Instant::now(), cpu());
    let v = f();
    (v, t.elapsed().as_secs_f64(), cpu() - c)
}

fn main() {
    let count = std::env::args()
        .skip(1)
        .find_map(|a| a.parse::<u64>().ok())
        .unwrap_or(100_000)
        .to_string();
    let v = [
        "zetafill", "fill", "-q", "--c", "1.3", "--count", &count, "--seed", "1", "-o", "x.svg",
    ];
    let cli = <zetafill_cli::Cli as clap::Parser>::try_parse_from(v).unwrap_or_else(|e| panic!("{e}"));
    let zetafill_cli::Command::Fill(a) = cli.command else {
        panic!("not fill")
    };
    let (run, draw) = zetafill_cli::plan::fill::resolve_as(&a, Format::Svg).unwrap_or_else(|e| panic!("{e}"));
    let ((doc, halt), wall, fill) = timed(|| zetafill_cli::cmd::fill::compute(&run).unwrap_or_else(|e| panic!("{e}")));
    assert!(halt.is_none(), "the fill halted");
    let opt = zetafill_cli::cmd::fill::svg_options(&doc, &draw).unwrap_or_else(|e| panic!("{e}"));
    println!("| step | circles | control: CPU s | now: CPU s | now / fill | bytes |");
    println!("|---|---:|---:|---:|---:|---:|");
    println!("| fill (cell sampler) | {count} | - | {fill:.2} (wall {wall:.2}) | - | - |");
    type Writer<'a> = Box<dyn Fn() -> Vec<u8> + 'a>;
    let writers: [(&str, Writer, Writer); 3] = [
        (
            "JSON",
            Box::new(|| control::json(&doc)),
            Box::new(|| json::render(&doc).unwrap_or_default()),
        ),
        ("CSV", Box::new(|| control::csv(&doc)), Box::new(|| csv::render(&doc))),
        (
            "SVG",
            Box::new(|| control::svg(&svg::picture(&doc, &opt))),
            Box::new(|| svg::write(&svg::picture(&doc, &opt))),
        ),
    ];
    for (name, old, new) in writers {
        let (a, _, t_old) = timed(old);
        let (b, _, t_new) = timed(new);
        assert!(a == b, "{name}: the writer and its control differ");
        println!(
            "| write {name} | {count} | {t_old:.3} | {t_new:.3} | {:.1}% | {} |",
            100.0 * t_new / fill,
            b.len()
        );
    }
}
