//! What `zetafill fill` and `zetafill line` share while they run: the progress bar, and the
//! message of a halt. The stop conditions and the slots they need are resolved in
//! [`crate::plan`].

pub use crate::plan::{check_min_size, sequence, slots, stop, Unit};

use crate::cmd::progress::{self, Bar};
use crate::error::CliError;
use zetafill::StepError;

/// A progress bar on standard error when it is a terminal and `--quiet` is not given.
pub fn progress_bar(quiet: bool, count: Option<u64>, unit: Unit) -> Option<Bar> {
    progress::bar(quiet, count, unit.plural)
}

/// The outcome of a run whose output is written: a halt becomes [`CliError::Halted`], naming
/// how many pieces the output holds and, for a halt, `advice(index, trials)`.
pub fn outcome(halt: Option<StepError>, unit: Unit, advice: impl Fn(u64, u64) -> &'static str) -> Result<(), CliError> {
    match halt {
        Some(StepError::Halted { index, trials }) => Err(CliError::Halted(format!(
            "halted at placement {index} after {trials} trials (the output holds the {index} {} placed before it): {}",
            unit.plural,
            advice(index, trials)
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
    fn stops_past_the_limit_name_their_flag() {
        let seq = sequence(1.0, 1.3, 1.0).expect("sequence");
        let found = zetafill::line::capacity(&seq, &stop(None, Some(0.999_999_99), None), UNIT.max);
        let e = slots(found, UNIT).expect_err("past the limit").to_string();
        assert!(e.starts_with("--fill: ") && e.contains("1048576 pieces"), "{e}");
        let found = zetafill::line::capacity(&seq, &stop(None, None, Some(1e-12)), UNIT.max);
        let e = slots(found, UNIT).expect_err("past the limit").to_string();
        assert!(e.starts_with("--min-size: ") && e.contains("pieces"), "{e}");
        assert_eq!(slots(Ok(78), UNIT).ok(), Some(78));
        // A bad offset is named.
        let e = sequence(1.0, 1.3, -1.0).expect_err("bad offset").to_string();
        assert!(e.starts_with("--n-offset: "), "{e}");
    }

    #[test]
    fn a_halt_names_the_pieces_kept() {
        assert!(outcome(None, UNIT, |_, _| "").is_ok());
        let e = outcome(Some(StepError::Halted { index: 12, trials: 3 }), UNIT, |_, _| "try again").expect_err("a halt");
        let m = e.to_string();
        assert!(
            m.contains("placement 12") && m.contains("holds the 12 pieces") && m.ends_with("try again"),
            "{m}"
        );
    }
}
