//! `--shape` and `--region` specs, and the number parsers every flag shares.

use crate::*;

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
pub(crate) fn places_shapes(region: Region<'_>) -> Result<(), String> {
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
    // A motif (svg:, glyph:) is read when the run is planned: its text form is what is checked.
    let Some(kinds) = arg.kinds() else {
        tally.add("motif");
        let again = spec::shape(&arg.name()).map_err(|e| format!("{text:?}: its name {:?} is refused: {e}", arg.name()))?;
        return if again == arg {
            Ok(())
        } else {
            Err(format!("{text:?}: its name {:?} reads back as {again:?}, not {arg:?}", arg.name()))
        };
    };
    let list = arg.list(zetafill::MixOrder::Cycle, 7);
    if kinds.is_empty() || kinds.len() > zetafill::MAX_MIX || !list.is_valid() || list.kinds() != kinds.as_slice() {
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
