//! `zetafill completions` and `zetafill man`: the completion script loads into a real bash and
//! completes subcommands and flags; every page renders through `man`, names its command and
//! lists every flag of it; a shell or page that does not exist is refused with exit 2 and
//! nothing on standard output.
// The shared checkers may use the platform's maths: only what the tool writes goes through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use clap::CommandFactory;
use common::{tmp, zf, zf_ok};
use std::process::Command;

/// What bash's completion function offers for the words `line` (the cursor at the end of
/// the last), called as bash calls it: with the command, the current word and the one before.
fn bash_completes(script: &str, line: &[&str]) -> Vec<String> {
    let quote = |w: &str| format!("'{w}'");
    let words = line.iter().map(|w| quote(w)).collect::<Vec<_>>().join(" ");
    let (cur, prev) = (line[line.len() - 1], line[line.len() - 2]);
    let program = format!(
        "{script}\nCOMP_WORDS=({words}); COMP_CWORD={}; COMP_LINE='{}'; COMP_POINT=${{#COMP_LINE}}; \
         _zetafill zetafill {} {}; printf '%s\\n' \"${{COMPREPLY[@]}}\"",
        line.len() - 1,
        line.join(" "),
        quote(cur),
        quote(prev)
    );
    let out = Command::new("bash").arg("-c").arg(program).output().expect("bash runs");
    assert!(out.status.success(), "bash: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter(|l| !l.is_empty())
        .map(str::to_string)
        .collect()
}

#[test]
fn bash_completes_subcommands_flags_and_values() {
    let dir = tmp();
    let script = String::from_utf8(zf_ok(dir.path(), &["completions", "bash"]).stdout).expect("UTF-8");
    let subcommands = bash_completes(&script, &["zetafill", ""]);
    for name in [
        "fill",
        "line",
        "space",
        "territory",
        "tile",
        "stats",
        "machines",
        "completions",
        "man",
    ] {
        assert!(subcommands.iter().any(|w| w == name), "{name} not among {subcommands:?}");
    }
    assert_eq!(bash_completes(&script, &["zetafill", "ter"]), ["territory"]);
    let flags = bash_completes(&script, &["zetafill", "fill", "--sam"]);
    assert_eq!(flags, ["--sampler"]);
    let values = bash_completes(&script, &["zetafill", "fill", "--sampler", ""]);
    for v in ["reference", "fast", "batched"] {
        assert!(values.iter().any(|w| w == v), "{v} not among {values:?}");
    }
    // The checker can fail: a flag fill does not have completes to nothing.
    assert!(bash_completes(&script, &["zetafill", "fill", "--no-such-fl"]).is_empty());
}

#[test]
fn every_shell_gets_a_script_that_names_every_subcommand() {
    let dir = tmp();
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let script = String::from_utf8(zf_ok(dir.path(), &["completions", shell]).stdout).expect("UTF-8");
        // fish names a long flag without its dashes (`-l seed`).
        for word in ["fill", "territory", "max-output-size", "seed"] {
            assert!(script.contains(word), "{shell}: no {word}");
        }
    }
}

/// The page rendered by `man` as plain text.
fn rendered(page: &[u8]) -> String {
    let dir = tmp();
    let path = dir.path().join("page.1");
    std::fs::write(&path, page).expect("write page");
    let out = Command::new("man")
        .arg("-l")
        .arg(&path)
        .env("MANWIDTH", "200")
        .env("MAN_KEEP_FORMATTING", "0")
        .env("MANPAGER", "cat")
        .env("PAGER", "cat")
        .output()
        .expect("man runs");
    assert!(out.status.success(), "man: {}", String::from_utf8_lossy(&out.stderr));
    // man underlines and emboldens with backspaces when it thinks it writes to a terminal.
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let mut plain = String::new();
    for ch in text.chars() {
        if ch == '\u{8}' {
            plain.pop();
        } else {
            plain.push(ch);
        }
    }
    plain.replace('\u{2010}', "-").replace("\u{2010}\n", "")
}

/// Every long flag of `cmd` appears in `text` (hyphenation joined back first).
fn missing_flags(cmd: &clap::Command, text: &str) -> Vec<String> {
    let joined: String = text.replace("-\n", "-").split_whitespace().collect::<Vec<_>>().join(" ");
    cmd.get_arguments()
        .filter(|a| !a.is_hide_set())
        .filter_map(|a| a.get_long())
        .map(|l| format!("--{l}"))
        .filter(|f| !joined.contains(f.as_str()))
        .collect()
}

#[test]
fn every_page_renders_and_lists_every_flag() {
    let dir = tmp();
    let tool = zetafill_cli::Cli::command();
    let page = rendered(&zf_ok(dir.path(), &["man"]).stdout);
    assert!(page.contains("zetafill(1)"), "{page}");
    for sub in tool.get_subcommands().filter(|s| !matches!(s.get_name(), "completions" | "man")) {
        let name = sub.get_name();
        let text = rendered(&zf_ok(dir.path(), &["man", name]).stdout);
        assert!(text.contains(&format!("zetafill-{name}(1)")), "{name}: {text}");
        let words: Vec<&str> = text.split_whitespace().collect();
        assert!(words.windows(2).any(|w| w == ["zetafill", name]), "{name}: no synopsis");
        assert_eq!(missing_flags(sub, &text), Vec::<String>::new(), "{name}");
    }
    // The checker can fail: the page of `line` does not list `fill`'s region flags.
    let fill = tool.find_subcommand("fill").expect("fill");
    let line = rendered(&zf_ok(dir.path(), &["man", "line"]).stdout);
    assert!(missing_flags(fill, &line).contains(&"--region".to_string()));
}

#[test]
fn a_shell_or_page_that_does_not_exist_is_refused() {
    let dir = tmp();
    for (args, named) in [(&["completions", "tcsh"][..], "<SHELL>"), (&["man", "nope"][..], "[SUBCOMMAND]")] {
        let out = zf(dir.path(), args);
        assert_eq!(out.code, 2, "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert!(
            out.stderr.contains(named) && out.stderr.contains("possible values"),
            "{}",
            out.stderr
        );
    }
}
