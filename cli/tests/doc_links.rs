//! Every relative link in the README, the changelog and `docs/*.md` leads somewhere: the file
//! exists, and a `#fragment` names a heading of the page it points to (GitHub's rule for
//! heading anchors). A page that loses a heading others link to is noticed here.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The repository's root folder.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The anchor GitHub gives a heading: lower case, spaces to hyphens, and every character but
/// letters, digits, hyphens and underscores dropped.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The anchors of a Markdown page's headings (outside fenced code).
fn anchors(page: &str) -> BTreeSet<String> {
    let mut fenced = false;
    let mut out = BTreeSet::new();
    for line in page.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        } else if !fenced && line.starts_with('#') {
            out.insert(slug(line.trim_start_matches('#')));
        }
    }
    out
}

/// The targets of a page's inline links `[text](target)`, outside fenced and inline code.
fn links(page: &str) -> Vec<String> {
    let mut fenced = false;
    let mut out = Vec::new();
    for line in page.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        // Inline code spans hold no links.
        let text: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
        let mut rest = text.as_str();
        while let Some(at) = rest.find("](") {
            let after = &rest[at + 2..];
            let Some(end) = after.find(')') else { break };
            out.push(after[..end].to_string());
            rest = &after[end..];
        }
    }
    out
}

/// What is wrong with `page`'s relative links (at `path`), one line each.
fn broken_links(path: &Path, page: &str) -> Vec<String> {
    let mut bad = Vec::new();
    for target in links(page) {
        if target.contains("://") || target.starts_with("mailto:") {
            continue;
        }
        let (file, fragment) = target.split_once('#').map_or((target.as_str(), None), |(f, a)| (f, Some(a)));
        if file.is_empty() {
            if fragment.is_some_and(|a| !anchors(page).contains(a)) {
                bad.push(format!("{}: {target}: no heading with that anchor", path.display()));
            }
            continue;
        }
        let dest = path.parent().unwrap_or(Path::new(".")).join(file);
        if !dest.exists() {
            bad.push(format!("{}: {target}: no such file", path.display()));
            continue;
        }
        if let Some(a) = fragment {
            let text = std::fs::read_to_string(&dest).unwrap_or_default();
            if dest.extension().is_some_and(|e| e == "md") && !anchors(&text).contains(a) {
                bad.push(format!("{}: {target}: no heading with that anchor", path.display()));
            }
        }
    }
    bad
}

/// The pages checked: the README, the changelog and every page of `docs/`.
fn pages() -> Vec<PathBuf> {
    let r = root();
    let mut v = vec![r.join("README.md"), r.join("CHANGELOG.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(r.join("docs"))
        .expect("docs/")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    v.extend(docs);
    v
}

#[test]
fn every_relative_link_leads_to_a_file_and_a_heading() {
    let mut bad = Vec::new();
    let mut count = 0;
    for path in pages() {
        let page = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        count += links(&page).len();
        bad.extend(broken_links(&path, &page));
    }
    assert!(count > 100, "only {count} links found: the parser lost them");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn the_checker_finds_a_missing_file_and_a_missing_heading() {
    let page =
        "# Top\n\n## `zetafill man` and more\n\nSee [a](#zetafill-man-and-more), [b](#gone), [c](no-such.md), [d](https://example.org).\n";
    let path = root().join("docs/contract.md");
    let bad = broken_links(&path, page);
    assert_eq!(bad.len(), 2, "{bad:?}");
    assert!(bad[0].contains("#gone") && bad[1].contains("no-such.md"), "{bad:?}");
    assert_eq!(slug(" What changes bytes, and the version"), "what-changes-bytes-and-the-version");
}
