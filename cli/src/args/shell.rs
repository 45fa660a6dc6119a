//! The flags of `zetafill completions` and `zetafill man`, which print what a shell or `man`
//! reads, generated from the command line itself.

use clap::Args;

/// `zetafill completions SHELL`.
#[derive(Debug, Args)]
pub struct CompletionsArgs {
    /// The shell to complete for. Bash: `zetafill completions bash > ~/.local/share/bash-completion/completions/zetafill`.
    pub shell: clap_complete::Shell,
}

/// `zetafill man [SUBCOMMAND]`.
#[derive(Debug, Args)]
pub struct ManArgs {
    /// The subcommand whose page to print (`zetafill-fill(1)`, ...); the tool's own page
    /// without one. For example `zetafill man fill > zetafill-fill.1`.
    #[arg(value_parser = ["fill", "line", "space", "territory", "tile", "stats", "machines"])]
    pub subcommand: Option<String>,
}
