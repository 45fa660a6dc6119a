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

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Usage(m) | CliError::Halted(m) | CliError::Io(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for CliError {}
