//! The JSON contract: `docs/zetafill.schema.json` is a valid draft 2020-12 schema; the
//! documents of every command (and the objects `stats --json` prints) follow it across their
//! shapes, regions, samplers, scalars and stops; and copies broken in one place each (a
//! required key gone, an unknown key, an unknown name, a negative count, a broken pairing of
//! keys) are refused, so the check can fail. Every other test's parsed documents go through
//! the same check ([`common::schema::check_document`]).
// The shared checkers may use the platform's maths: only what the tool writes goes through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::schema::{schema_errors, schema_value};
use common::{tmp, zf, zf_ok};
use serde_json::{json, Value};
use std::path::Path;

#[test]
fn the_schema_is_a_valid_draft_2020_12_schema() {
    let schema = schema_value();
    assert_eq!(schema["$schema"], "https://json-schema.org/draft/2020-12/schema");
    jsonschema::meta::validate(&schema).unwrap_or_else(|e| panic!("not a valid schema: {e}"));
    // The meta-schema check can fail.
    assert!(jsonschema::meta::validate(&json!({ "type": "no-such-type" })).is_err());
}

/// Runs `zetafill ARGS -o NAME` in `dir` and returns the document written.
fn written(dir: &Path, args: &str, name: &str) -> Value {
    let mut a: Vec<&str> = args.split(' ').collect();
    a.extend(["-o", name, "-q"]);
    if a[0] == "stats" {
        a.truncate(a.len() - 3);
        a.push("--json");
        let out = zf_ok(dir, &a);
        return serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{args}: {e}"));
    }
    // A halted fill (exit 3) writes its document too.
    let out = zf(dir, &a);
    assert!(out.code == 0 || out.code == 3, "zetafill {args}: {}", out.stderr);
    let bytes = std::fs::read(dir.join(name)).unwrap_or_else(|e| panic!("{args}: {e}"));
    serde_json::from_slice(&bytes).unwrap_or_else(|e| panic!("{args}: {e}"))
}

/// One command of each kind of document, and each flag that adds, drops or changes keys.
const RUNS: &[&str] = &[
    "fill --count 60",
    "fill --shape square --rotate none --count 60",
    "fill --shape rect:2 --count 60",
    "fill --shape triangle --scalar fixed --count 60",
    "fill --shape polygon:6 --count 60",
    "fill --shape star:5:0.5 --n-offset 4 --count 60",
    "fill --shape ring:0.5 --n-offset 4 --count 60",
    "fill --shape blob:0.3 --count 40",
    "fill --shape noisy:0.3 --count 30",
    "fill --shape mix:circle,square --mix-order random --count 60",
    "fill --shape mix:ring:0.4,star:6:0.6,triangle --n-offset 6 --count 60",
    "fill --shape svg:region.svg --n-offset 4 --count 40",
    "fill --shape mix:svg:region.svg,glyph:Z,circle --n-offset 6 --count 40",
    "fill --region circle:80 --count 60",
    "fill --region annulus:80:30 --n-offset 6 --count 60",
    "fill --region polygon:0,0,100,0,100,100,0,100/30,30,70,30,70,70,30,70 --n-offset 10 --count 60",
    "fill --region polygon:0,0,60,0,60,60,0,60/100,0,160,0,160,60,100,60 --n-offset 4 --count 40",
    "fill --region svg:region.svg --c 1.2 --n-offset 5 --count 60",
    "fill --region mask:picture.png:0.4 --region-width 150 --n-offset 30 --count 60",
    "fill --region text:AB --text-size 60 --letter-spacing 2 --n-offset 40 --count 60",
    "fill --periodic --shape square --gap 0.5 --count 80",
    "fill --density noise:gradient:30:3:0.6:1.5 --periodic --count 60",
    "fill --density image:picture.png,invert,gamma=2,floor=0.1 --count 60",
    "fill --cells 64 --count 60",
    "fill --sampler reference --count 60",
    "fill --sampler batched --batch 8 --threads 2 --count 60",
    "fill --fill 0.5",
    "fill --min-size 8",
    "fill --dimension 1.6 --count 40",
    "fill --max-trials 5 --count 500 --n-offset 3 --sampler reference",
    "line --count 60",
    "line --periodic --sampler reference --gap 0.2 --count 60",
    "line --fill 0.6",
    "line --max-trials 2 --count 500 --sampler reference",
    "space --count 40",
    "space --shape cube --count 40",
    "space --shape tetrahedron --n-offset 4 --count 40",
    "space --shape shell:0.5 --count 40",
    "space --shape torus:0.3 --c 1.1 --n-offset 2 --count 20",
    "space --shape mix:sphere,torus:0.4,shell:0.6 --mix-order random --count 30",
    "space --region ball:50 --n-offset 4 --count 40",
    "space --region boxball:80:80:80:25 --n-offset 8 --count 40",
    "space --region box:60:60:40 --periodic --n-offset 2 --count 40",
    "space --scalar fixed --sampler reference --count 30",
    "space --max-trials 3 --count 500 --sampler reference",
    "territory --points 200",
    "territory --sites 4 --points 200 --render cells --region circle:90",
    "territory --points 200 --render filled --uniform",
    "territory --points 200 --region polygon:0,0,100,0,50,80 --color 0.1,0.5,0.9",
    "tile --tries 1500",
    "tile --tries 1500 --render voronoi --style filled",
    "stats zeta --c 1.3",
    "stats gasket --c 1.3 --n 100",
    "stats trials --count 50 --runs 2",
];

/// The documents of [`RUNS`] (with their command lines), plus a territory seeded from a fill
/// and `stats dimension` of a fill, in a folder holding the pictures and outlines they read.
fn documents(dir: &Path) -> Vec<(String, Value)> {
    std::fs::write(
        dir.join("region.svg"),
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><path d="M0 0H100V100H0Z M30 30V70H70V30Z" fill-rule="evenodd"/></svg>"#,
    )
    .expect("write the outline");
    common::png_picture(&dir.join("picture.png"), 64, 64, |x, y| {
        (x as i32 - 32).pow(2) + (y as i32 - 32).pow(2) < 600
    });
    let mut docs: Vec<(String, Value)> = RUNS
        .iter()
        .enumerate()
        .map(|(i, args)| (args.to_string(), written(dir, args, &format!("d{i}.json"))))
        .collect();
    for args in ["territory --sites-from d0.json --sites 3", "stats dimension d0.json"] {
        docs.push((args.to_string(), written(dir, args, "derived.json")));
    }
    docs
}

#[test]
fn every_command_writes_documents_that_follow_the_schema() {
    let dir = tmp();
    let docs = documents(dir.path());
    let mut modes = std::collections::BTreeSet::new();
    for (args, doc) in &docs {
        let errors = schema_errors(doc);
        assert!(errors.is_empty(), "zetafill {args}:\n{}", errors.join("\n"));
        if let Some(m) = doc.get("mode").and_then(Value::as_str) {
            modes.insert(m.to_string());
        }
    }
    assert_eq!(
        modes.into_iter().collect::<Vec<_>>(),
        ["fill", "line", "space", "territory", "tile"]
    );
}

/// `doc` with `change` made to it.
fn broken(doc: &Value, change: impl FnOnce(&mut Value)) -> Value {
    let mut d = doc.clone();
    change(&mut d);
    d
}

/// Removes `key` from the object at `v`.
fn without(v: &mut Value, key: &str) {
    v.as_object_mut().map(|o| o.remove(key)).expect("an object");
}

#[test]
fn documents_broken_in_one_place_are_refused() {
    let dir = tmp();
    let docs = documents(dir.path());
    let of = |args: &str| docs.iter().find(|(a, _)| a == args).map(|(_, d)| d.clone()).expect(args);
    let fill = of("fill --count 60");
    let ring = of("fill --shape ring:0.5 --n-offset 4 --count 60");
    let mix = of("fill --shape mix:circle,square --mix-order random --count 60");
    let batched = of("fill --sampler batched --batch 8 --threads 2 --count 60");
    let line = of("line --count 60");
    let space = of("space --count 40");
    let territory = of("territory --points 200");
    let zeta = of("stats zeta --c 1.3");
    let cases: Vec<(&str, Value)> = vec![
        ("a required key gone", broken(&fill, |d| without(d, "zeta"))),
        ("the sampler gone", broken(&fill, |d| without(&mut d["params"], "sampler"))),
        ("an unknown key", broken(&fill, |d| d["extra"] = json!(1))),
        (
            "an unknown key in a shape",
            broken(&fill, |d| d["shapes"][0]["colour"] = json!("red")),
        ),
        ("an unknown kind", broken(&fill, |d| d["shapes"][0]["kind"] = json!("hexagon"))),
        (
            "a ring without its hole",
            broken(&ring, |d| without(&mut d["shapes"][0], "inner_radius")),
        ),
        ("negative trials", broken(&fill, |d| d["shapes"][0]["trials"] = json!(-1))),
        ("a fractional index", broken(&fill, |d| d["shapes"][1]["index"] = json!(1.5))),
        (
            "a 3D centre in a 2D fill",
            broken(&fill, |d| d["shapes"][0]["center"] = json!([1.0, 2.0, 3.0])),
        ),
        ("an unknown sampler", broken(&fill, |d| d["params"]["sampler"] = json!("quick"))),
        ("an unknown stop", broken(&fill, |d| d["stats"]["stop"] = json!("timeout"))),
        (
            "halted with the count reached",
            broken(&fill, |d| d["stats"]["halted"] = json!(true)),
        ),
        ("another version", broken(&fill, |d| d["version"] = json!(2))),
        ("an unknown mode", broken(&fill, |d| d["mode"] = json!("fil"))),
        ("a mix without its order", broken(&mix, |d| without(&mut d["params"], "mix_order"))),
        (
            "batched without its batch",
            broken(&batched, |d| without(&mut d["params"], "batch")),
        ),
        (
            "a batch without the batched sampler",
            broken(&fill, |d| d["params"]["batch"] = json!(8)),
        ),
        ("no stop condition", broken(&fill, |d| without(&mut d["params"], "count"))),
        (
            "a segment of another kind",
            broken(&line, |d| d["shapes"][0]["kind"] = json!("circle")),
        ),
        ("a line with a fill's area", broken(&line, |d| d["area"] = json!(1.0))),
        ("an unknown solid", broken(&space, |d| d["solids"][0]["kind"] = json!("pyramid"))),
        (
            "a 2D centre in space",
            broken(&space, |d| d["solids"][0]["center"] = json!([1.0, 2.0])),
        ),
        (
            "a periodic territory",
            broken(&territory, |d| d["region"]["periodic"] = json!(true)),
        ),
        ("an unknown key in stats", broken(&zeta, |d| d["extra"] = json!(0))),
    ];
    for (what, doc) in &cases {
        assert!(!schema_errors(doc).is_empty(), "{what}: accepted");
    }
    // The unchanged documents pass, so each refusal is the change's.
    for d in [&fill, &ring, &mix, &batched, &line, &space, &territory, &zeta] {
        assert_eq!(schema_errors(d), Vec::<String>::new());
    }
}
