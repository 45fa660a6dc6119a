//! Every example command in the README and in `docs/*.md` runs as written, and every picture
//! shown beside a command is what that command makes today.
//!
//! A page's examples are its indented lines that start with `zetafill ` (or with the
//! `cargo run ... --` form of the main job). They run in order, through the built binary, in a
//! temporary folder of the page's own that holds a `docs/` subfolder. Each must exit 0 and
//! write its `-o` file (or, with no `-o`, print something). Two kinds of output are compared
//! byte for byte with the committed pictures:
//!
//! - an output written to `docs/NAME` where the repository has `docs/NAME`;
//! - the output of a command whose arguments are exactly those of a gallery file
//!   `examples/gallery/NAME.args`, against the gallery's picture.
//!
//! Each page keeps at least the number of examples listed in [`MINIMUM`], so a page that loses
//! its examples is noticed.

use std::path::{Path, PathBuf};
use std::process::Command;

const CARGO_RUN: &str = "cargo run --release -p zetafill-cli -- ";

/// Pages and the fewest example commands each must hold.
const MINIMUM: &[(&str, usize)] = &[
    ("README.md", 12),
    ("docs/cli.md", 12),
    ("docs/colour.md", 4),
    ("docs/height-maps.md", 3),
    ("docs/plotting.md", 8),
    ("docs/territory.md", 7),
    ("docs/cobblestones.md", 2),
    ("docs/tile.md", 6),
    ("docs/stats.md", 7),
    ("docs/symmetry.md", 3),
];

/// The repository's root folder.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A page's example commands, as argument lists (comments after `#` dropped).
fn examples(page: &str) -> Vec<Vec<String>> {
    page.lines()
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

/// The committed pictures that commands must reproduce: (arguments, picture) for every gallery
/// `.args` file.
fn gallery() -> Vec<(Vec<String>, PathBuf)> {
    let dir = root().join("examples/gallery");
    let mut out = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("examples/gallery") {
        let path = entry.expect("gallery entry").path();
        if path.extension().is_some_and(|e| e == "args") {
            let text = std::fs::read_to_string(&path).expect("args file");
            let args: Vec<String> = text.split_whitespace().map(String::from).collect();
            if let Some(o) = output_of(&args) {
                let picture = dir.join(o);
                out.push((args, picture));
            }
        }
    }
    out
}

/// The committed file an output must equal, if any.
fn committed(args: &[String], gallery: &[(Vec<String>, PathBuf)]) -> Option<PathBuf> {
    if let Some((_, picture)) = gallery.iter().find(|(a, _)| a.as_slice() == args) {
        return Some(picture.clone());
    }
    let o = output_of(args)?;
    let name = o.strip_prefix("docs/")?;
    let path = root().join("docs").join(name);
    path.is_file().then_some(path)
}

/// Runs every example in `dir`; the first failure, described.
fn run_all(examples: &[Vec<String>], dir: &Path, gallery: &[(Vec<String>, PathBuf)]) -> Result<(), String> {
    for args in examples {
        let shown = format!("zetafill {}", args.join(" "));
        if args.iter().any(|a| a.contains(['"', '\'', '>', '|', '$'])) {
            return Err(format!("{shown}: quotes, redirections and substitutions are not supported here"));
        }
        let out = Command::new(env!("CARGO_BIN_EXE_zetafill"))
            .args(args)
            .current_dir(dir)
            .output()
            .map_err(|e| format!("{shown}: {e}"))?;
        if !out.status.success() {
            return Err(format!(
                "{shown}: exit {:?}\n{}",
                out.status.code(),
                String::from_utf8_lossy(&out.stderr)
            ));
        }
        let Some(o) = output_of(args) else {
            if out.stdout.is_empty() {
                return Err(format!("{shown}: printed nothing"));
            }
            continue;
        };
        let written = std::fs::read(dir.join(o)).unwrap_or_default();
        if written.is_empty() {
            return Err(format!("{shown}: wrote nothing to {o}"));
        }
        if let Some(picture) = committed(args, gallery) {
            let expected = std::fs::read(&picture).map_err(|e| format!("{}: {e}", picture.display()))?;
            if written != expected {
                return Err(format!(
                    "{shown}: its output differs from the committed {} (regenerate the picture, or show the command that makes it)",
                    picture.display()
                ));
            }
        }
    }
    Ok(())
}

#[test]
fn every_documented_example_runs_as_written() {
    let gallery = gallery();
    assert!(gallery.len() >= 10, "only {} gallery pictures found", gallery.len());
    let mut pages: Vec<String> = vec!["README.md".into()];
    let mut docs: Vec<String> = std::fs::read_dir(root().join("docs"))
        .expect("docs/")
        .map(|e| e.expect("docs entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".md"))
        .map(|n| format!("docs/{n}"))
        .collect();
    docs.sort();
    pages.extend(docs);
    for (page, _) in MINIMUM {
        assert!(pages.iter().any(|p| p == page), "{page} is missing");
    }

    // Each page's examples run in a folder of their own: two threads take every other page.
    let check = |page: &String| -> (usize, Vec<String>) {
        let mut failures = Vec::new();
        let text = std::fs::read_to_string(root().join(page)).unwrap_or_else(|e| panic!("{page}: {e}"));
        let all = examples(&text);
        let least = MINIMUM.iter().find(|(p, _)| p == page).map_or(0, |&(_, n)| n);
        if all.len() < least {
            failures.push(format!("{page}: {} example commands, at least {least} expected", all.len()));
        }
        let dir = tempfile::tempdir().expect("tempdir");
        std::fs::create_dir(dir.path().join("docs")).expect("docs");
        if let Err(e) = run_all(&all, dir.path(), &gallery) {
            failures.push(format!("{page}: {e}"));
        }
        (all.len(), failures)
    };
    let results: Vec<(usize, Vec<String>)> = std::thread::scope(|s| {
        let odd = s.spawn(|| pages.iter().skip(1).step_by(2).map(check).collect::<Vec<_>>());
        let mut all: Vec<_> = pages.iter().step_by(2).map(check).collect();
        all.extend(odd.join().unwrap_or_else(|_| panic!("an example thread failed")));
        all
    });
    let total: usize = results.iter().map(|r| r.0).sum();
    let failures: Vec<String> = results.into_iter().flat_map(|r| r.1).collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        total >= MINIMUM.iter().map(|&(_, n)| n).sum::<usize>(),
        "{total} example commands in all"
    );

    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let main_job = examples(&readme);
    assert!(
        main_job
            .iter()
            .any(|a| a.first().is_some_and(|c| c == "fill") && output_of(a) == Some("fill.svg")),
        "the main job is in the README"
    );
}

#[test]
fn the_checker_reports_a_failing_example() {
    let gallery = gallery();
    let dir = tempfile::tempdir().expect("tempdir");
    std::fs::create_dir(dir.path().join("docs")).expect("docs");

    // An example that cannot work: an A4 page too small for the region.
    let broken = examples("    zetafill fill --count 300 --region rect:300:300 --page a4 --center -o pens.svg\n");
    assert_eq!(broken.len(), 1);
    assert!(run_all(&broken, dir.path(), &gallery).is_err(), "a failing example is reported");

    // A picture that is not what its command makes: the zoom of the 1D fill with seed 1, whose
    // third and fourth rows fall inside one segment, against the committed seed-4 picture.
    let stale = examples("    zetafill line --c 1.4 --count 30000 --periodic --seed 1 --render zoom --pixels 600 -o docs/line-zoom.png\n");
    let e = run_all(&stale, dir.path(), &gallery).expect_err("a stale picture is reported");
    assert!(e.contains("differs from the committed"), "{e}");

    // A gallery picture is held to the command with exactly its `.args`; another command that
    // writes a file of the same name is not.
    let tile = examples("    zetafill tile -q -o tile.svg\n");
    let other = examples("    zetafill tile -q --seed 2 -o tile.svg\n");
    assert!(committed(&tile[0], &gallery).is_some_and(|p| p.ends_with("examples/gallery/tile.svg")));
    assert!(committed(&other[0], &gallery).is_none());
}
