//! The `zetafill` command-line tool: argument parsing (clap, [`args`]), one checked plan per
//! command ([`plan`]), one module per subcommand ([`cmd`]), the file system ([`io`]), and the
//! single place where outcomes become exit codes ([`run_main`]). The drawing model, the shared
//! geometry, the writers and the error values are the crate `zetafill-render`, re-exported
//! here as [`model`], [`geometry`], [`output`] and [`error`]. Which module may use which is in
//! docs/architecture.md.

#![deny(missing_docs)]

pub mod args;
pub mod cmd;
pub mod io;
pub mod plan;

pub use zetafill_render::{error, geometry, model, output};

pub use args::{Cli, Command};
use clap::Parser;
use error::CliError;
use std::ffi::OsString;

/// Runs the tool on `args` (including the program name); returns the exit code after
/// printing any message on stderr.
pub fn run_main<I, T>(args: I) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(c) => c,
        Err(e) => {
            // clap prints help and version to stdout (exit 0), usage errors to stderr (exit 2).
            let _ = e.print();
            return if e.use_stderr() { 2 } else { 0 };
        }
    };
    match run(cli) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}

/// Runs a parsed command. First, for every command alike, an output that is one of the
/// command's inputs is refused (nothing is read, computed or written).
pub fn run(cli: Cli) -> Result<(), CliError> {
    io::inputs::forget_reads();
    io::inputs::refuse_overwrites(&plan::files::of(&cli.command))?;
    match cli.command {
        Command::Fill(a) => cmd::fill::run(&plan::fill::resolve(&a)?),
        Command::Line(a) => cmd::line::run(&plan::line::resolve(&a)?),
        Command::Space(a) => cmd::space::run(&plan::space::resolve(&a)?),
        Command::Territory(a) => cmd::territory::run(&plan::territory::resolve(&a)?),
        Command::Tile(a) => cmd::tile::run(&plan::tile::resolve(&a)?),
        Command::Stats(s) => cmd::stats::run(&plan::stats::resolve(&s)?),
        Command::Machines(m) => cmd::machines::run(&plan::machines::resolve(&m)),
        Command::Completions(a) => print_generated(|out| {
            clap_complete::generate(a.shell, &mut <Cli as clap::CommandFactory>::command(), "zetafill", out);
            Ok(())
        }),
        Command::Man(a) => print_generated(|out| man_page(a.subcommand.as_deref(), out)),
    }
}

/// The roff page of the tool, or of `subcommand` (titled `zetafill-NAME`), into `out`.
pub fn man_page(subcommand: Option<&str>, out: &mut dyn std::io::Write) -> std::io::Result<()> {
    let tool = <Cli as clap::CommandFactory>::command();
    match subcommand.and_then(|name| tool.find_subcommand(name).map(|c| (name, c))) {
        Some((name, c)) => {
            clap_mangen::Man::new(c.clone().name(format!("zetafill-{name}")).bin_name(format!("zetafill {name}"))).render(out)
        }
        None => clap_mangen::Man::new(tool).render(out),
    }
}

/// Writes what `make` generates to standard output (a closed pipe is an I/O error, exit 1).
fn print_generated(make: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>) -> Result<(), CliError> {
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    make(&mut out)
        .and_then(|()| std::io::Write::flush(&mut out))
        .map_err(|e| CliError::Io(format!("cannot write to standard output: {e}")))
}
