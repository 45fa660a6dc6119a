//! `zetafill machines` resolved: list the built-in machine profiles, or show one (a built-in
//! name or a profile file) as TOML; and the refusal of a profile that cannot be shown.

use crate::args::machines::{MachinesArgs, MachinesCommand};
use crate::error::CliError;

/// A checked `zetafill machines`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum MachinesPlan {
    /// List the built-ins.
    List,
    /// Print one profile: a built-in name or a FILE.toml.
    Show(String),
}

/// What `zetafill machines` was asked to do (listing when no subcommand is given).
pub fn resolve(a: &MachinesArgs) -> MachinesPlan {
    match &a.command {
        None | Some(MachinesCommand::List) => MachinesPlan::List,
        Some(MachinesCommand::Show { name }) => MachinesPlan::Show(name.clone()),
    }
}

/// A profile named by `machines show NAME` that cannot be read or checked (`why`).
pub fn profile_error(why: String) -> CliError {
    CliError::arg("NAME", why)
}
