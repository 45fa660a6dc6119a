//! The flags of `zetafill machines`: list the built-in profiles, or show one as TOML.

use clap::{Args, Subcommand};

/// Arguments of `zetafill machines`.
#[derive(Debug, Args)]
pub struct MachinesArgs {
    /// What to do (default: list the built-ins).
    #[command(subcommand)]
    pub command: Option<MachinesCommand>,
}

/// Subcommands of `zetafill machines`.
#[derive(Debug, Subcommand)]
pub enum MachinesCommand {
    /// List the built-in profiles.
    List,
    /// Print a built-in profile (or check and print a FILE.toml) as TOML.
    Show {
        /// A built-in name or a FILE.toml.
        name: String,
    },
}
