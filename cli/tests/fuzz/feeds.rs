//! Feeds: every built-in profile in inches (and in mm), with any origin, travel mode and
//! arcs, and any `--feed` and `--travel-feed` from 1 to 1,000,000 mm/min. The G-code must pass
//! the safety invariants, and every feed read back (converted to mm/min) must be what was
//! asked: within 0.1 % in inches, to the whole mm/min in mm.

use super::machines::{plot_flags, small_fill_gcode, PlotFlags};
use crate::common::safety::feed_faults;
use crate::*;
use zetafill_cli::output::machine::Machine;

/// A feed in mm/min: log-uniform over the whole range, near its ends, near whole inches per
/// minute, and values that used to round to 1 in/min.
fn feed() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => (0.0f64..6.0).prop_map(|e| 10f64.powf(e)),
        2 => 1.0f64..40.0,
        1 => (1u32..40_000).prop_map(|k| f64::from(k) * 25.4),
        1 => select(vec![1.0, 1.0000001, 1.27, 12.7, 13.0, 30.0, 37.0, 38.1, 1000.0, 999_999.9, 1_000_000.0]),
    ]
    .prop_map(|f: f64| f.clamp(1.0, 1_000_000.0))
}

/// (profile text, drawing feed, travel feed, inches).
fn fed_profile() -> impl Strategy<Value = (String, f64, f64, bool)> {
    (
        select(Machine::builtin_names()),
        select(vec!["bottom-left", "top-left", "center"]),
        select(vec!["rapid", "feed"]),
        any::<bool>(),
        feed(),
        feed(),
        prop::bool::weighted(0.8),
    )
        .prop_map(|(name, origin, travel, arcs, draw, travel_feed, inch)| {
            let text = Machine::builtin_text(name)
                .unwrap_or("")
                .replacen("units = \"mm\"", if inch { "units = \"inch\"" } else { "units = \"mm\"" }, 1)
                .replacen("origin = \"bottom-left\"", &format!("origin = \"{origin}\""), 1)
                .replacen("travel = \"rapid\"", &format!("travel = \"{travel}\""), 1)
                .replacen("arcs = true", &format!("arcs = {arcs}"), 1);
            (text, draw, travel_feed, inch)
        })
}

#[test]
fn fuzz_feeds() {
    let dir = Scratch::new();
    let tally = Tally::new(&["programs", "inch", "feeds checked"]);
    fuzz(
        "feeds",
        300,
        (fed_profile(), plot_flags()),
        |((text, draw, travel, inch), flags)| {
            let m = Machine::parse(&text).map_err(|e| format!("{e}\n{text}"))?;
            // The flags of a small fill, their own feed replaced by the case's.
            let mut extra: Vec<String> = Vec::new();
            let mut it = flags.extra.iter();
            while let Some(a) = it.next() {
                if a == "--feed" {
                    it.next();
                } else {
                    extra.push(a.clone());
                }
            }
            extra.extend(["--feed".into(), format!("{draw}"), "--travel-feed".into(), format!("{travel}")]);
            let flags = PlotFlags { extra, ..flags };
            let path = dir.write("fed.toml", text.as_bytes());
            let Some(bytes) = small_fill_gcode(&path, &flags)? else {
                return Ok(());
            };
            let program = String::from_utf8(bytes).map_err(|_| "the G-code is not UTF-8".to_string())?;
            let r = replay(&program, &profile_from_toml(&text));
            if let Some(e) = r.errors.first() {
                return Err(format!("unsafe G-code ({} faults, first {e}) from profile\n{text}", r.errors.len()));
            }
            let faults = if inch {
                feed_faults(&r, m.units.per_mm(), draw, &[travel], 1e-3, 0.0)
            } else {
                feed_faults(&r, 1.0, draw, &[travel], 0.0, 0.5 + 1e-9)
            };
            if let Some(f) = faults.first() {
                return Err(format!("{} feeds not as asked ({draw}, {travel} mm/min), first {f}", faults.len()));
            }
            tally.add("programs");
            if inch {
                tally.add("inch");
            }
            for _ in &r.feeds {
                tally.add("feeds checked");
            }
            Ok(())
        },
    );
    tally.report("feeds");
    assert!(
        tally.get("inch") * 2 >= cases(300) as u64,
        "fewer than half the cases wrote inch G-code"
    );
}
