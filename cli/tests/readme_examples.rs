//! Every example command in the README runs as written: each indented line that starts with
//! `zetafill ` (or the `cargo run ... --` form of the main job) is run, in order, in one
//! temporary folder, and must exit 0 and write its `-o` file.

use std::path::Path;
use std::process::Command;

const CARGO_RUN: &str = "cargo run --release -p zetafill-cli -- ";

/// The README's example commands, as argument lists (comments after `#` dropped).
fn examples(readme: &str) -> Vec<Vec<String>> {
    readme
        .lines()
        .filter_map(|l| l.strip_prefix("    "))
        .filter_map(|l| l.strip_prefix("zetafill ").or_else(|| l.strip_prefix(CARGO_RUN)))
        .map(|l| l.split(" #").next().unwrap_or(l))
        .map(|l| l.split_whitespace().map(String::from).collect())
        .collect()
}

/// The value of `-o`/`--output` in `args`.
fn output_of(args: &[String]) -> Option<&str> {
    let at = args.iter().position(|a| a == "-o" || a == "--output")?;
    args.get(at + 1).map(String::as_str)
}

/// Runs every example in `dir`; the first failure, described.
fn run_all(examples: &[Vec<String>], dir: &Path) -> Result<(), String> {
    for args in examples {
        if args.iter().any(|a| a.contains(['"', '\''])) {
            return Err(format!("{args:?}: quoted arguments are not supported here"));
        }
        let out = Command::new(env!("CARGO_BIN_EXE_zetafill"))
            .args(args)
            .current_dir(dir)
            .output()
            .map_err(|e| format!("{args:?}: {e}"))?;
        if !out.status.success() {
            return Err(format!(
                "zetafill {}: {:?}\n{}",
                args.join(" "),
                out.status.code(),
                String::from_utf8_lossy(&out.stderr)
            ));
        }
        let Some(o) = output_of(args) else {
            return Err(format!("{args:?}: no -o"));
        };
        let written = std::fs::metadata(dir.join(o)).map(|m| m.len()).unwrap_or(0);
        if written == 0 {
            return Err(format!("zetafill {}: wrote nothing to {o}", args.join(" ")));
        }
    }
    Ok(())
}

#[test]
fn every_readme_example_runs_as_written() {
    let readme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../README.md")).expect("README.md");
    let all = examples(&readme);
    assert!(all.len() >= 15, "only {} example commands found", all.len());
    assert!(
        all.iter()
            .any(|a| a.first().is_some_and(|c| c == "fill") && output_of(a) == Some("fill.svg")),
        "the main job is among them"
    );
    let dir = tempfile::tempdir().expect("tempdir");
    std::fs::create_dir(dir.path().join("docs")).expect("docs");
    if let Err(e) = run_all(&all, dir.path()) {
        panic!("{e}");
    }

    // The checker fails on an example that cannot work: an A4 page too small for the region.
    let broken = examples("    zetafill fill --count 300 --region rect:300:300 --page a4 --center -o pens.svg\n");
    assert_eq!(broken.len(), 1);
    assert!(run_all(&broken, dir.path()).is_err(), "a failing example is reported");
}
