//! The layers of `cli/src/` and `render/src/` as docs/architecture.md draws them: this test reads the table of
//! "The rules of the layering" (which module may name which, and which may name clap), then
//! every source file, and refuses a path that reaches a module its row does not list, clap
//! where its row says no, a module mounted with `#[path]`, and any cycle between the
//! top-level modules. Comments, doc comments and string literals are left out; `use` items,
//! paths in code and paths in attributes (clap's `value_parser = crate::…`) all count, and
//! `super::` chains are followed to where they lead.
//!
//! The checker is also run on made-up trees, each with one fault, to prove it reports it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The crate root's files: they may name everything.
const ROOT: &str = "";

/// What docs/architecture.md allows: for each top-level module, the modules it may name, and
/// whether it may name clap.
#[derive(Debug, Default)]
struct Rules {
    may_use: BTreeMap<String, BTreeSet<String>>,
    clap: BTreeSet<String>,
}

/// The module a table cell names: `cmd/` is `cmd`, `error.rs` is `error`, the root's files
/// are the root.
fn module_name(cell: &str) -> String {
    let name = cell.trim().trim_end_matches('/').trim_end_matches(".rs");
    if name == "lib" || name == "main" {
        ROOT.to_string()
    } else {
        name.to_string()
    }
}

/// The names in backquotes in a table cell.
fn quoted(cell: &str) -> Vec<String> {
    cell.split('`').skip(1).step_by(2).map(module_name).collect()
}

/// The rules from the table whose header is `| layer | may use | clap |`.
fn rules_from_doc(doc: &str) -> Result<Rules, String> {
    let mut lines = doc.lines().skip_while(|l| !l.starts_with("| layer | may use | clap |"));
    if lines.next().is_none() {
        return Err("no `| layer | may use | clap |` table".into());
    }
    let mut rules = Rules::default();
    for row in lines.skip(1).take_while(|l| l.starts_with('|')) {
        let cells: Vec<&str> = row.split('|').map(str::trim).collect();
        let [_, layer, uses, clap, ..] = cells.as_slice() else {
            return Err(format!("a row without three cells: {row}"));
        };
        let allowed: BTreeSet<String> = quoted(uses).into_iter().collect();
        if allowed.is_empty() && *uses != "nothing" && *uses != "everything" {
            return Err(format!("a row that lists no module: {row}"));
        }
        for name in quoted(layer) {
            if *clap == "yes" {
                rules.clap.insert(name.clone());
            }
            rules.may_use.insert(name, allowed.clone());
        }
    }
    if rules.may_use.is_empty() {
        return Err("the table has no rows".into());
    }
    Ok(rules)
}

/// Rust source with comments and the insides of string and character literals blanked out
/// (newlines kept, so line numbers still hold).
fn strip(src: &str) -> String {
    let c: Vec<char> = src.chars().collect();
    let mut out = String::with_capacity(src.len());
    let blank = |ch: char| if ch == '\n' { '\n' } else { ' ' };
    let ident = |ch: char| ch.is_alphanumeric() || ch == '_';
    let mut i = 0;
    while i < c.len() {
        let next = c.get(i + 1).copied();
        if c[i] == '/' && next == Some('/') {
            while i < c.len() && c[i] != '\n' {
                out.push(' ');
                i += 1;
            }
        } else if c[i] == '/' && next == Some('*') {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    out.push(blank(c[i]));
                    i += 1;
                }
            }
        } else if c[i] == 'r' && (i == 0 || !ident(c[i - 1]) || c[i - 1] == 'b') && matches!(next, Some('"' | '#')) {
            // A raw string r"…" or r#"…"#: no escapes, ends at the quote and as many #.
            let mut j = i + 1;
            while c.get(j) == Some(&'#') {
                j += 1;
            }
            if c.get(j) != Some(&'"') {
                out.push(c[i]);
                i += 1;
                continue;
            }
            let hashes = j - i - 1;
            out.push('r');
            out.push_str(&"#".repeat(hashes));
            out.push('"');
            i = j + 1;
            while i < c.len() {
                if c[i] == '"' && (1..=hashes).all(|k| c.get(i + k) == Some(&'#')) {
                    out.push('"');
                    out.push_str(&"#".repeat(hashes));
                    i += 1 + hashes;
                    break;
                }
                out.push(blank(c[i]));
                i += 1;
            }
        } else if c[i] == '"' {
            out.push('"');
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    out.push(' ');
                    i += 1;
                }
                if let Some(&ch) = c.get(i) {
                    out.push(blank(ch));
                }
                i += 1;
            }
            out.push('"');
            i += 1;
        } else if c[i] == '\'' && (next == Some('\\') || c.get(i + 2) == Some(&'\'')) {
            // A character literal ('x', '\n', '\u{..}'); a lifetime ('a) has no closing quote.
            out.push('\'');
            i += 1;
            if c.get(i) == Some(&'\\') {
                out.push(' ');
                i += 1;
            }
            while i < c.len() && c[i] != '\'' {
                out.push(' ');
                i += 1;
            }
            out.push('\'');
            i += 1;
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

/// A token of stripped source: an identifier, `::` or one other character, with its line.
#[derive(Debug, Clone, PartialEq)]
struct Token {
    text: String,
    line: usize,
}

fn tokens(code: &str) -> Vec<Token> {
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let (mut i, mut line) = (0, 1);
    while i < c.len() {
        let ch = c[i];
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch.is_alphabetic() || ch == '_' {
            let start = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push(Token {
                text: c[start..i].iter().collect(),
                line,
            });
        } else if ch == ':' && c.get(i + 1) == Some(&':') {
            out.push(Token { text: "::".into(), line });
            i += 2;
        } else {
            out.push(Token { text: ch.into(), line });
            i += 1;
        }
    }
    out
}

/// The module path of a file under `src/`: `cmd/tile/mod.rs` is `cmd::tile`,
/// `cmd/tile/render/tests.rs` is `cmd::tile::render::tests`, `lib.rs` the root.
fn module_path(file: &str) -> Vec<String> {
    let mut parts: Vec<String> = file.trim_end_matches(".rs").split('/').map(str::to_string).collect();
    if parts.last().is_some_and(|p| p == "mod") || (parts.len() == 1 && (parts[0] == "lib" || parts[0] == "main")) {
        parts.pop();
    }
    parts
}

/// Every path that starts at `crate` or `super` in `toks`, resolved from the module `here`
/// (inline `mod x { … }` blocks included) to the absolute path it names, with its line. A
/// group `a::{b::c, d}` gives one path per member.
fn crate_paths(toks: &[Token], here: &[String]) -> Vec<(Vec<String>, usize)> {
    let mut out = Vec::new();
    // Inline modules: (name, brace depth at which it opened).
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0;
    let mut i = 0;
    while i < toks.len() {
        let t = toks[i].text.as_str();
        match t {
            "{" => depth += 1,
            "}" => {
                depth -= 1;
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
            }
            "mod" if toks.get(i + 2).is_some_and(|b| b.text == "{") => {
                if let Some(name) = toks.get(i + 1) {
                    inline.push((name.text.clone(), depth));
                }
            }
            _ => {}
        }
        let starts = (t == "crate" || t == "super") && (i == 0 || toks[i - 1].text != "::");
        if starts && toks.get(i + 1).is_some_and(|n| n.text == "::") {
            let mut module: Vec<String> = here.iter().cloned().chain(inline.iter().map(|(n, _)| n.clone())).collect();
            let mut j = i;
            let mut valid = true;
            if t == "crate" {
                module.clear();
                j += 2;
            } else {
                while toks.get(j).is_some_and(|s| s.text == "super") && toks.get(j + 1).is_some_and(|n| n.text == "::") {
                    valid &= module.pop().is_some();
                    j += 2;
                }
            }
            if valid {
                let line = toks[i].line;
                for rest in tails(toks, j) {
                    let mut path = module.clone();
                    path.extend(rest);
                    out.push((path, line));
                }
            }
        }
        i += 1;
    }
    out
}

/// The paths that follow position `j` (just after a `::`): `a::b`, a glob, or a group
/// `{a::b as c, d}`, each cut where it stops being a path.
fn tails(toks: &[Token], j: usize) -> Vec<Vec<String>> {
    fn text(toks: &[Token], j: usize) -> Option<&str> {
        toks.get(j).map(|t| t.text.as_str())
    }
    fn walk(toks: &[Token], mut j: usize, mut path: Vec<String>, out: &mut Vec<Vec<String>>) -> usize {
        loop {
            match text(toks, j) {
                Some("{") => {
                    j += 1;
                    loop {
                        if text(toks, j) == Some("}") {
                            return j + 1;
                        }
                        j = walk(toks, j, path.clone(), out);
                        match text(toks, j) {
                            Some(",") => j += 1,
                            Some("}") => return j + 1,
                            _ => return j,
                        }
                    }
                }
                Some(name) if name.starts_with(|c: char| c.is_alphabetic() || c == '_') => {
                    if name != "self" {
                        path.push(name.to_string());
                    }
                    j += 1;
                    if text(toks, j) == Some("::") {
                        j += 1;
                        continue;
                    }
                    if text(toks, j) == Some("as") {
                        j += 2;
                    }
                    out.push(path);
                    return j;
                }
                Some("*") => {
                    out.push(path);
                    return j + 1;
                }
                _ => {
                    out.push(path);
                    return j;
                }
            }
        }
    }
    let mut out = Vec::new();
    walk(toks, j, Vec::new(), &mut out);
    out
}

/// What the checker found in a tree.
#[derive(Debug, Default)]
struct Report {
    /// Each fault, one line each.
    faults: Vec<String>,
    /// Which top-level module names which (the root left out).
    edges: BTreeMap<String, BTreeSet<String>>,
}

/// Checks `files` (paths under `src/` with `/` separators, and their text) against `rules`.
fn check(files: &[(String, String)], rules: &Rules) -> Report {
    let mut report = Report::default();
    let tops: BTreeSet<String> = files.iter().filter_map(|(f, _)| module_path(f).first().cloned()).collect();
    for top in &tops {
        if !rules.may_use.contains_key(top) {
            report
                .faults
                .push(format!("{top}: a module the table of docs/architecture.md does not list"));
        }
    }
    for (file, text) in files {
        let here = module_path(file);
        let top = here.first().cloned().unwrap_or_default();
        let toks = tokens(&strip(text));
        let allowed = rules.may_use.get(&top);
        for (path, line) in crate_paths(&toks, &here) {
            let Some(to) = path.first() else { continue };
            if *to == top || !tops.contains(to) || top == ROOT {
                continue;
            }
            report.edges.entry(top.clone()).or_default().insert(to.clone());
            if !allowed.is_some_and(|a| a.contains(to)) {
                let may: Vec<&str> = allowed.into_iter().flatten().map(String::as_str).collect();
                report.faults.push(format!(
                    "{file}:{line}: {top} names crate::{} ({to} is not among what {top} may use: {})",
                    path.join("::"),
                    if may.is_empty() { "nothing".to_string() } else { may.join(", ") }
                ));
            }
        }
        for (k, t) in toks.iter().enumerate() {
            let prev = k.checked_sub(1).map(|p| toks[p].text.as_str());
            let next = toks.get(k + 1).map(|n| n.text.as_str());
            if t.text == "clap" && prev != Some("::") && matches!(next, Some("::") | Some(";")) && !rules.clap.contains(&top) {
                report
                    .faults
                    .push(format!("{file}:{}: {top} names clap, which only the rows marked so may", t.line));
            }
            if t.text == "path" && prev == Some("[") && next == Some("=") {
                report
                    .faults
                    .push(format!("{file}:{}: a module mounted with #[path]; use a folder", t.line));
            }
        }
    }
    if let Some(cycle) = find_cycle(&report.edges) {
        report.faults.push(format!("a cycle between modules: {}", cycle.join(" -> ")));
    }
    report
}

/// A cycle in `edges`, as the modules along it (the first again at the end), if any.
fn find_cycle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        done: &mut BTreeSet<String>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = stack.iter().position(|s| s == node) {
            let mut cycle = stack[at..].to_vec();
            cycle.push(node.to_string());
            return Some(cycle);
        }
        if done.contains(node) {
            return None;
        }
        stack.push(node.to_string());
        for next in edges.get(node).into_iter().flatten() {
            if let Some(c) = visit(next, edges, done, stack) {
                return Some(c);
            }
        }
        stack.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    edges.keys().find_map(|n| visit(n, edges, &mut done, &mut Vec::new()))
}

/// Every `.rs` file under `dir`, as (path under `dir` with `/`, text), in name order.
fn read_tree(dir: &Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        let entries = std::fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display()));
        for entry in entries {
            let p = entry.unwrap_or_else(|e| panic!("{}: {e}", d.display())).path();
            if p.is_dir() {
                todo.push(p);
            } else if p.extension().is_some_and(|e| e == "rs") {
                let rel = p.strip_prefix(dir).unwrap_or(&p).components();
                let name: Vec<String> = rel.map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
                let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
                out.push((name.join("/"), text));
            }
        }
    }
    out.sort();
    out
}

fn doc_rules() -> Rules {
    let doc = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/architecture.md");
    let text = std::fs::read_to_string(&doc).unwrap_or_else(|e| panic!("{}: {e}", doc.display()));
    rules_from_doc(&text).unwrap_or_else(|e| panic!("docs/architecture.md: {e}"))
}

#[test]
fn the_table_of_layers_has_no_cycle() {
    let rules = doc_rules();
    let edges: BTreeMap<String, BTreeSet<String>> = rules
        .may_use
        .iter()
        .filter(|(m, _)| m.as_str() != ROOT)
        .map(|(m, to)| (m.clone(), to.clone()))
        .collect();
    assert_eq!(find_cycle(&edges), None);
    for to in edges.values().flatten() {
        assert!(rules.may_use.contains_key(to), "{to} is used but has no row");
    }
    assert!(!rules.clap.contains("cmd") && !rules.clap.contains("output") && rules.clap.contains("args"));
}

#[test]
fn every_file_of_the_cli_keeps_to_its_layer() {
    // The CLI and the render crate (its model, geometry, writers and errors, re-exported by the
    // CLI under the same names) are one tree of layers.
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let cli = read_tree(&manifest.join("src"));
    let render = read_tree(&manifest.join("../render/src"));
    assert!(
        cli.len() > 30 && render.len() > 30,
        "read only {} and {} files",
        cli.len(),
        render.len()
    );
    let files: Vec<(String, String)> = cli.into_iter().chain(render).collect();
    let report = check(&files, &doc_rules());
    assert!(report.faults.is_empty(), "{}", report.faults.join("\n"));
    // The checker saw the edges every command needs, so a blind checker cannot pass.
    for (from, to) in [("plan", "args"), ("cmd", "plan"), ("output", "model"), ("geometry", "model")] {
        assert!(report.edges.get(from).is_some_and(|t| t.contains(to)), "{from} -> {to} not seen");
    }
}

/// A small tree that keeps the rules, to which each control adds one fault.
fn fake_tree() -> Vec<(String, String)> {
    [
        ("lib.rs", "pub mod args;\npub mod cmd;\npub mod model;\npub mod plan;\npub use args::Cli;\n"),
        ("args/mod.rs", "use crate::model::Thing;\n#[derive(clap::Parser)]\npub struct Cli;\n"),
        ("plan/mod.rs", "use crate::args::Cli;\nuse crate::{args::Cli as C, model};\n"),
        ("cmd/mod.rs", "pub mod tile;\n"),
        ("cmd/tile/mod.rs", "use crate::plan::TilePlan;\nuse super::super::model::Thing;\n"),
        (
            "model/mod.rs",
            "//! See crate::cmd::tile.\n/// Not crate::plan either.\npub struct Thing;\nconst S: &str = \"crate::cmd::x\";\nconst R: &str = r#\"use crate::plan;\"#;\nfn f<'a>(x: &'a str) -> char { '\"' }\n/* crate::cmd /* nested */ crate::args */\n",
        ),
    ]
    .iter()
    .map(|(f, t)| (f.to_string(), t.to_string()))
    .collect()
}

fn fake_rules() -> Rules {
    rules_from_doc(
        "text\n\n| layer | may use | clap |\n|---|---|---|\n| `lib.rs`, `main.rs` | everything | yes |\n| `cmd/` | `plan/`, `model/` | no |\n| `plan/` | `args/`, `model/` | yes |\n| `args/` | `model/` | yes |\n| `model/` | nothing | no |\n\nmore text\n",
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

/// The faults found in the fake tree with `file` set to `text`.
fn faults_with(file: &str, text: &str) -> Vec<String> {
    let mut files = fake_tree();
    files.retain(|(f, _)| f != file);
    files.push((file.to_string(), text.to_string()));
    check(&files, &fake_rules()).faults
}

#[test]
fn the_fake_tree_passes_and_its_comments_and_strings_do_not_count() {
    let report = check(&fake_tree(), &fake_rules());
    assert_eq!(report.faults, Vec::<String>::new());
    assert!(
        report.edges.get("cmd").is_some_and(|t| t.contains("model")),
        "super::super not followed"
    );
}

#[test]
fn the_checker_reports_an_upward_import_and_the_cycle_it_makes() {
    let faults = faults_with("plan/mod.rs", "use crate::args::Cli;\nuse crate::cmd::tile::Render;\n");
    assert!(
        faults
            .iter()
            .any(|f| f.starts_with("plan/mod.rs:2: plan names crate::cmd::tile::Render")),
        "{faults:?}"
    );
    assert!(
        faults.iter().any(|f| f.contains("a cycle between modules: cmd -> plan -> cmd")),
        "{faults:?}"
    );
}

#[test]
fn the_checker_reports_upward_paths_in_groups_attributes_code_and_super_chains() {
    for (file, text, want) in [
        (
            "args/mod.rs",
            "#[arg(value_parser = crate::cmd::tile::parse)]\npub x: u8,\n",
            "args/mod.rs:1: args names crate::cmd::tile::parse",
        ),
        (
            "model/mod.rs",
            "use crate::{args, plan::X};\n",
            "model/mod.rs:1: model names crate::args",
        ),
        (
            "model/mod.rs",
            "fn f() { crate::plan::go(); }\n",
            "model/mod.rs:1: model names crate::plan::go",
        ),
        (
            "model/deep/mod.rs",
            "mod inner {\n    use super::super::super::cmd::X;\n}\n",
            "model/deep/mod.rs:2: model names crate::cmd::X",
        ),
        ("model/mod.rs", "use clap::Parser;\n", "model/mod.rs:1: model names clap"),
        (
            "model/mod.rs",
            "#[path = \"../x.rs\"]\nmod x;\n",
            "model/mod.rs:1: a module mounted with #[path]",
        ),
        (
            "extra/mod.rs",
            "pub struct X;\n",
            "extra: a module the table of docs/architecture.md does not list",
        ),
    ] {
        let faults = faults_with(file, text);
        assert!(faults.iter().any(|f| f.starts_with(want)), "{want}: {faults:?}");
    }
}

#[test]
fn a_doc_without_the_table_is_refused() {
    assert!(rules_from_doc("# Architecture\n\nno table here\n").is_err());
    assert!(rules_from_doc("| layer | may use | clap |\n|---|---|---|\n| `cmd/` | plan | no |\n").is_err());
}
