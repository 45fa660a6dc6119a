//! The command's errors and the one place they become exit codes.
//!
//! 0 success; 2 bad usage or bad input (the message names the argument and what to change);
//! 3 halted (the output holds every shape placed so far); 1 anything else (I/O).

use std::fmt;

/// A failed run.
#[derive(Debug)]
pub enum CliError {
    /// Bad usage or input: exit 2, nothing written.
    Usage(String),
    /// The fill halted: exit 3, the output was written with every shape placed so far.
    Halted(String),
    /// Anything else (I/O): exit 1.
    Io(String),
}

impl CliError {
    /// The process exit code for this error.
    pub fn exit_code(&self) -> i32 {
        match self {
            CliError::Usage(_) => 2,
            CliError::Halted(_) => 3,
            CliError::Io(_) => 1,
        }
    }

    /// A usage error about one argument: "ARG: what is wrong".
    pub fn arg(arg: &str, msg: impl fmt::Display) -> Self {
        CliError::Usage(format!("{arg}: {msg}"))
    }
}

/// The error of a write into an output that failed.
pub fn io_error(e: std::io::Error) -> CliError {
    CliError::Io(format!("cannot write the output: {e}"))
}

/// A number as a message shows it: as Rust writes it in the usual range, in exponent form when
/// its size is extreme (so that 1e-300 is not written with three hundred digits).
pub fn num(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v != 0.0 && v.is_finite() && !(1e-6..1e15).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Usage(m) | CliError::Halted(m) | CliError::Io(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for CliError {}

#[cfg(test)]
mod tests {
    use super::num;

    #[test]
    fn extreme_numbers_are_written_short() {
        assert_eq!(num(1e-300), "1e-300");
        assert_eq!(num(-2.5e300), "-2.5e300");
        assert_eq!(num(0.001), "0.001");
        assert_eq!(num(1300.5), "1300.5");
        assert_eq!(num(0.0), "0");
        assert_eq!(num(f64::INFINITY), "inf");
        assert_eq!(num(f64::NAN), "nan");
    }
}
