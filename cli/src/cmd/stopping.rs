//! What `zetafill fill` and `zetafill line` share about running to a stop: the stop
//! conditions, the slots they can need, the progress bar, and the message of a halt.

use crate::error::CliError;
use std::io::IsTerminal;
use zetafill::StepError;
use zetafill::Stop;

/// What a run places: `"shapes"` (2D) or `"segments"` (1D), with its limit per run.
#[derive(Debug, Clone, Copy)]
pub struct Unit {
    /// The plural noun used in messages.
    pub plural: &'static str,
    /// The most one run may hold.
    pub max: u64,
}

/// The stop conditions from `--count`, `--fill` and `--min-size`: 2000 pieces when none is
/// given.
pub fn stop(count: Option<u64>, fill: Option<f64>, min_size: Option<f64>) -> Stop {
    let count = match (count, fill, min_size) {
        (None, None, None) => Some(2000),
        (c, _, _) => c,
    };
    Stop { count, fill, min_size }
}

/// How many slots the stop conditions can need, with one to spare: at most `--count`; for
/// `--fill f` the first `k` with `zeta(c, N + k) <= (1 - f) zeta(c, N)` (the first `k` pieces
/// cover `f` of the region); for `--min-size m` the first `k` whose width `width(k)`
/// (decreasing in `k`) is below `m`. Each search doubles `k`, so it errs high by at most 2x.
pub fn capacity(c: f64, n: f64, stop: &Stop, unit: Unit, width: impl Fn(u64) -> f64) -> Result<u64, CliError> {
    let zeta = zetafill::internals::zeta::zeta(c, n).map_err(|e| CliError::arg("--n-offset", e))?;
    // The smallest power of two at which `more` fails, or None past the unit's limit.
    let first_failing = |more: &dyn Fn(u64) -> bool| {
        let mut hi = 1u64;
        while more(hi) && hi <= unit.max {
            hi *= 2;
        }
        (hi <= unit.max).then_some(hi)
    };
    let mut slots = stop.count.unwrap_or(u64::MAX);
    if let Some(f) = stop.fill {
        let target = (1.0 - f) * zeta;
        let tail = |k: u64| zetafill::internals::zeta::hurwitz_zeta(c, n + k as f64).unwrap_or(0.0);
        let hi = first_failing(&|k| tail(k) > target).ok_or_else(|| {
            CliError::arg(
                "--fill",
                format!("{f} needs more than {} {} at this c; lower it or raise --c", unit.max, unit.plural),
            )
        })?;
        slots = slots.min(hi);
    }
    if let Some(m) = stop.min_size {
        let hi = first_failing(&|k| width(k) >= m).ok_or_else(|| {
            CliError::arg(
                "--min-size",
                format!("{m} mm needs more than {} {}; raise it", unit.max, unit.plural),
            )
        })?;
        slots = slots.min(hi);
    }
    Ok(slots.saturating_add(1).min(unit.max))
}

/// A progress bar on standard error when it is a terminal and `--quiet` is not given.
pub fn progress_bar(quiet: bool, count: Option<u64>, unit: Unit) -> Option<indicatif::ProgressBar> {
    if quiet || !std::io::stderr().is_terminal() {
        return None;
    }
    let b = match count {
        Some(k) => indicatif::ProgressBar::new(k),
        None => indicatif::ProgressBar::new_spinner(),
    };
    let template = format!("{{bar:40}} {{pos}}/{{len}} {}, {{elapsed}} (eta {{eta}})", unit.plural);
    if let Ok(style) = indicatif::ProgressStyle::with_template(&template) {
        b.set_style(style);
    }
    Some(b)
}

/// The outcome of a run whose output is written: a halt becomes [`CliError::Halted`], naming
/// how many pieces the output holds and, for a trial-limit halt, `advice(index)`.
pub fn outcome(halt: Option<StepError>, unit: Unit, advice: impl Fn(u64) -> &'static str) -> Result<(), CliError> {
    match halt {
        Some(StepError::Halted { index, trials }) => Err(CliError::Halted(format!(
            "halted at placement {index} after {trials} trials (the output holds the {index} {} placed before it): {}",
            unit.plural,
            advice(index)
        ))),
        Some(e) => Err(CliError::Halted(format!(
            "{e}; the output holds every {} placed before it",
            singular(unit)
        ))),
        None => Ok(()),
    }
}

/// "shape" or "segment".
fn singular(unit: Unit) -> &'static str {
    unit.plural.strip_suffix('s').unwrap_or(unit.plural)
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: Unit = Unit {
        plural: "pieces",
        max: 1 << 20,
    };

    #[test]
    fn no_condition_means_two_thousand() {
        let s = stop(None, None, None);
        assert_eq!((s.count, s.fill, s.min_size), (Some(2000), None, None));
        let s = stop(None, Some(0.5), None);
        assert_eq!((s.count, s.fill), (None, Some(0.5)));
    }

    #[test]
    fn capacity_covers_every_stop_condition() {
        let (c, n) = (1.3, 1.0);
        let zeta = zetafill::internals::zeta::zeta(c, n).expect("zeta");
        // --count k: k slots and one to spare.
        assert_eq!(capacity(c, n, &stop(Some(77), None, None), UNIT, |_| 1.0).expect("capacity"), 78);
        // --fill f: the first cap - 1 pieces cover at least f, half as many do not.
        for f in [0.1, 0.5, 0.8] {
            let cap = capacity(c, n, &stop(None, Some(f), None), UNIT, |_| 1.0).expect("capacity");
            let covered = |k: u64| 1.0 - zetafill::internals::zeta::hurwitz_zeta(c, n + k as f64).expect("zeta") / zeta;
            assert!(covered(cap - 1) >= f, "f {f} cap {cap}");
            assert!(cap <= 2 || covered((cap - 1) / 2) < f, "f {f} cap {cap}");
        }
        // --min-size m: piece cap - 1 is narrower than m.
        let width = |k: u64| 100.0 / (k as f64 + 1.0);
        let cap = capacity(c, n, &stop(None, None, Some(0.7)), UNIT, width).expect("capacity");
        assert!(width(cap - 1) < 0.7 && width((cap - 1) / 2) >= 0.7, "cap {cap}");
        // The tighter condition wins.
        assert_eq!(capacity(c, n, &stop(Some(5), None, Some(0.7)), UNIT, width).expect("capacity"), 6);
    }

    #[test]
    fn capacity_past_the_limit_names_the_flag() {
        let e = capacity(1.3, 1.0, &stop(None, Some(0.999_999_99), None), UNIT, |_| 1.0).expect_err("past the limit");
        assert!(e.to_string().contains("--fill") && e.to_string().contains("pieces"), "{e}");
        let e = capacity(1.3, 1.0, &stop(None, None, Some(1e-9)), UNIT, |_| 1.0).expect_err("past the limit");
        assert!(e.to_string().contains("--min-size"), "{e}");
    }

    #[test]
    fn a_halt_names_the_pieces_kept() {
        assert!(outcome(None, UNIT, |_| "").is_ok());
        let e = outcome(Some(StepError::Halted { index: 12, trials: 3 }), UNIT, |_| "try again").expect_err("a halt");
        let m = e.to_string();
        assert!(
            m.contains("placement 12") && m.contains("holds the 12 pieces") && m.ends_with("try again"),
            "{m}"
        );
    }
}
