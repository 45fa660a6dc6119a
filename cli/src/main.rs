//! The `zetafill` binary: everything lives in the `zetafill_cli` library; this only maps the
//! outcome to the process exit code.

fn main() {
    std::process::exit(zetafill_cli::run_main(std::env::args_os()));
}
