//! The hostile-input corpus (`tests/hostile/cases.txt` at the workspace root, with its input
//! files in `tests/hostile/files/`): every numeric flag at NaN, infinities, negative, zero and
//! huge values, malformed specs, binary, empty and endless files, machine profiles with every
//! refused word. Each case must exit 2 with a short message that names its argument, carries
//! no control character, no NaN and no number hundreds of digits long, writes nothing, and
//! leaves an existing output untouched.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;
use std::path::{Path, PathBuf};

const KEEP: &[u8] = b"an existing output, which must survive\n";
const OUTPUTS: [&str; 4] = ["out.json", "out.svg", "out.png", "out.gcode"];

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/hostile")
}

/// The cases: (argument to name, command words).
fn cases() -> Vec<(String, Vec<String>)> {
    let text = std::fs::read_to_string(corpus_dir().join("cases.txt")).unwrap_or_else(|e| panic!("cases.txt: {e}"));
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| {
            let (flag, cmd) = l.split_once('\t').unwrap_or_else(|| panic!("no tab in '{l}'"));
            (flag.to_string(), cmd.split(' ').map(str::to_string).collect())
        })
        .collect()
}

/// A folder with the corpus's input files under `files/` and every output name holding
/// [`KEEP`].
fn workdir() -> tempfile::TempDir {
    let dir = tmp();
    let files = dir.path().join("files");
    std::fs::create_dir(&files).unwrap_or_else(|e| panic!("{e}"));
    for e in std::fs::read_dir(corpus_dir().join("files")).unwrap_or_else(|e| panic!("{e}")) {
        let p = e.unwrap_or_else(|e| panic!("{e}")).path();
        std::fs::copy(&p, files.join(p.file_name().unwrap_or_default())).unwrap_or_else(|e| panic!("{e}"));
    }
    for o in OUTPUTS {
        std::fs::write(dir.path().join(o), KEEP).unwrap_or_else(|e| panic!("{e}"));
    }
    dir
}

/// What is wrong with one run of a hostile case, if anything.
fn judge(dir: &Path, flag: &str, args: &[String]) -> Option<String> {
    let before = listing(dir);
    let words: Vec<&str> = args.iter().map(String::as_str).collect();
    let o = zf(dir, &words);
    let msg = o.stderr.trim_end();
    let mut wrong = Vec::new();
    if o.code != 2 {
        wrong.push(format!("exit {} instead of 2", o.code));
    }
    if !names_flag(msg, flag) {
        wrong.push(format!("the message does not name {flag}"));
    }
    if msg.len() > 600 {
        wrong.push(format!("a message of {} bytes", msg.len()));
    }
    if msg.chars().any(|c| c.is_control() && c != '\n') {
        wrong.push("a control character in the message".into());
    }
    if msg.contains("NaN") || msg.contains("inf mm") || msg.contains("panicked") {
        wrong.push("NaN, inf mm or a panic in the message".into());
    }
    let longest_digits = msg.split(|c: char| !c.is_ascii_digit()).map(str::len).max().unwrap_or(0);
    if longest_digits > 30 {
        wrong.push(format!("a number of {longest_digits} digits in the message"));
    }
    if !o.stdout.is_empty() {
        wrong.push("output on stdout".into());
    }
    for out in OUTPUTS {
        if read(&dir.join(out)) != KEEP {
            wrong.push(format!("{out} was changed"));
            std::fs::write(dir.join(out), KEEP).unwrap_or_else(|e| panic!("{e}"));
        }
    }
    let after = listing(dir);
    if after != before {
        wrong.push(format!("files appeared or went: {before:?} -> {after:?}"));
    }
    (!wrong.is_empty()).then(|| format!("zetafill {}: {} ({msg})", args.join(" "), wrong.join("; ")))
}

#[test]
fn every_hostile_input_is_refused_cleanly() {
    let cases = cases();
    assert!(cases.len() >= 100, "the corpus holds {} cases", cases.len());
    let dir = workdir();
    let failures: Vec<String> = cases.iter().filter_map(|(flag, args)| judge(dir.path(), flag, args)).collect();
    assert!(
        failures.is_empty(),
        "{} of {} cases:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

/// The judge fails a run that succeeds, one that names another flag, and one that writes.
#[test]
fn the_judge_can_fail() {
    let dir = workdir();
    let d = dir.path();
    let words = |s: &str| s.split(' ').map(str::to_string).collect::<Vec<_>>();
    let good = judge(d, "--count", &words("fill --count 5 -o fresh.json")).unwrap_or_default();
    assert!(good.contains("exit 0 instead of 2") && good.contains("files appeared"), "{good}");
    let other = judge(d, "--gap", &words("fill --c nan -o out.json")).unwrap_or_default();
    assert!(other.contains("does not name --gap"), "{other}");
    let over = judge(d, "--count", &words("fill --count 5 -o out.json")).unwrap_or_default();
    assert!(over.contains("out.json was changed"), "{over}");
    assert_eq!(judge(d, "--c", &words("fill --c nan -o out.json")), None);
}
