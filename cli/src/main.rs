//! The `zetafill` binary: everything lives in the `zetafill_cli` library; this only maps the
//! outcome to the process exit code, after arranging that an interrupt removes any temporary
//! output file.

fn main() {
    zetafill_cli::io::write::remove_temporaries_on_signal();
    std::process::exit(zetafill_cli::run_main(std::env::args_os()));
}
