//! The fast writers against their control: every fill below is written as JSON, CSV and SVG
//! (several drawing styles) by the tool's writers and by `output::control` (numbers through
//! the standard formatter, JSON through `serde_json`; SVG built with the `svg` crate by both), and the
//! bytes must be equal. The fills cover every shape kind, both scalars, each region kind and
//! periodic images, 20,000 shapes in the largest. `a_changed_byte_is_caught` shows the
//! comparison fails when one number differs.

use zetafill_cli::model::doc::FillDoc;
use zetafill_cli::output::{control, csv, json, svg};
use zetafill_cli::plan::format::Format;

/// Runs `zetafill fill ARGS` in process: the document and the drawing plan.
fn fill(args: &str) -> (FillDoc, zetafill_cli::plan::fill::FillDraw) {
    let mut v = vec!["zetafill", "fill", "-q", "-o", "x.svg"];
    v.extend(args.split_whitespace());
    let cli = <zetafill_cli::Cli as clap::Parser>::try_parse_from(&v).unwrap_or_else(|e| panic!("{args}: {e}"));
    let zetafill_cli::Command::Fill(a) = cli.command else {
        panic!("not fill")
    };
    let (run, draw) = zetafill_cli::plan::fill::resolve_as(&a, Format::Svg).unwrap_or_else(|e| panic!("{args}: {e}"));
    let (doc, halt) = zetafill_cli::cmd::fill::compute(&run).unwrap_or_else(|e| panic!("{args}: {e}"));
    assert!(halt.is_none(), "{args}: halted, so the fill is smaller than asked");
    (doc, draw)
}

/// `Err` with the first differing offset and the text around it.
fn same(what: &str, fast: &[u8], control: &[u8]) -> Result<(), String> {
    if fast == control {
        return Ok(());
    }
    let at = fast
        .iter()
        .zip(control)
        .position(|(a, b)| a != b)
        .unwrap_or(fast.len().min(control.len()));
    let around = |b: &[u8]| String::from_utf8_lossy(&b[at.saturating_sub(40)..(at + 40).min(b.len())]).into_owned();
    Err(format!(
        "{what}: first difference at byte {at} of {} / {}\nfast:    {}\ncontrol: {}",
        fast.len(),
        control.len(),
        around(fast),
        around(control)
    ))
}

/// Every format of a fill, fast against control.
fn check(args: &str) {
    let (doc, draw) = fill(args);
    let fast = json::render(&doc).unwrap_or_else(|e| panic!("{e}"));
    same(&format!("{args} JSON"), &fast, &control::json(&doc)).unwrap_or_else(|e| panic!("{e}"));
    same(&format!("{args} CSV"), &csv::render(&doc), &control::csv(&doc)).unwrap_or_else(|e| panic!("{e}"));
    let opt = zetafill_cli::cmd::fill::svg_options(&doc, &draw).unwrap_or_else(|e| panic!("{e}"));
    let pic = svg::picture(&doc, &opt);
    same(&format!("{args} SVG"), &svg::write(&pic), &control::svg(&pic)).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn twenty_thousand_mixed_shapes() {
    check("--shape mix:circle,square,triangle,ring:0.5,rect:2,polygon:6 --c 1.3 --count 20000 --seed 3");
}

#[test]
fn stars_blobs_and_a_fixed_point_fill() {
    check("--shape mix:star:5:0.45,blob:0.2,circle --n-offset 3 --count 600 --seed 4");
    check("--shape mix:circle,square --scalar fixed --c 1.3 --count 2000 --seed 5");
}

#[test]
fn regions_periodic_images_and_drawing_styles() {
    check("--shape ring:0.6 --region circle:80 --n-offset 3 --count 3000 --style filled --palette 264653,2a9d8f,e9c46a");
    check("--region annulus:90:30 --n-offset 4 --count 3000 --layers size-bands:4 --page a4 --margin 10");
    check("--shape square --periodic --count 3000 --hatch 0.8:30 --background f4f1de");
    check("--region polygon:0,0,150,0,75,120 --c 1.25 --n-offset 3 --count 1500 --gap 0.05 --boundary");
}

#[test]
fn a_changed_byte_is_caught() {
    let (mut doc, _) = fill("--count 300 --seed 2");
    let fast = (json::render(&doc).unwrap_or_default(), csv::render(&doc));
    // One ulp on one radius: the shortest round-trip forms differ.
    if let Some(r) = doc.shapes[150].radius.as_mut() {
        *r = f64::from_bits(r.to_bits() + 1);
    }
    assert!(same("JSON", &fast.0, &control::json(&doc)).is_err());
    assert!(same("CSV", &fast.1, &control::csv(&doc)).is_err());
    // One coordinate moved by a micrometre: four decimals see it.
    let opt = zetafill_cli::cmd::fill::svg_options(&doc, &fill("--count 300 --seed 2").1).unwrap_or_else(|e| panic!("{e}"));
    let before = svg::write(&svg::picture(&doc, &opt));
    doc.shapes[150].center[0] += 0.001;
    let e = same("SVG", &before, &control::svg(&svg::picture(&doc, &opt)))
        .err()
        .unwrap_or_default();
    assert!(e.contains("first difference at byte"), "{e}");
}
