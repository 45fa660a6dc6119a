//! Reference outputs: every `examples/gallery/NAME.args` (a `fill`, `line`, `tile` or `territory` command) run in
//! process must write exactly the committed picture. Set `ZETAFILL_REGENERATE=1` to rewrite the pictures after an intended
//! change (and look at them before committing).

use std::path::{Path, PathBuf};
use zetafill_tests::parse_fill;

fn gallery() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/gallery")
}

/// The first differing byte offset, if any.
fn first_difference(a: &[u8], b: &[u8]) -> Option<usize> {
    if a == b {
        return None;
    }
    Some(a.iter().zip(b).position(|(x, y)| x != y).unwrap_or(a.len().min(b.len())))
}

fn render(args_file: &Path) -> (PathBuf, Vec<u8>) {
    let text = std::fs::read_to_string(args_file).unwrap_or_default();
    let mut args: Vec<String> = vec!["zetafill".into()];
    args.extend(text.split_whitespace().map(String::from));
    use clap::Parser;
    let command = zetafill_cli::Cli::try_parse_from(&args)
        .unwrap_or_else(|e| panic!("{}: {e}", args_file.display()))
        .command;
    if let zetafill_cli::Command::Tile(t) = command {
        let format = zetafill_cli::plan::format::TileFormat::resolve(t.output.format, &t.output.output)
            .unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        let (_, bytes) = zetafill_cli::plan::tile::resolve_as(&t, format)
            .and_then(|(run, draw)| zetafill_cli::cmd::tile::output(&run, &draw, format))
            .unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        return (gallery().join(&t.output.output), bytes);
    }
    if let zetafill_cli::Command::Territory(t) = command {
        let format = zetafill_cli::plan::format::TerritoryFormat::resolve(t.output.format, &t.output.output)
            .unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        let bytes = zetafill_cli::plan::territory::resolve_as(&t, format)
            .and_then(|(run, draw)| zetafill_cli::cmd::territory::output(&run, &draw, format))
            .unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        return (gallery().join(&t.output.output), bytes);
    }
    if let zetafill_cli::Command::Line(l) = command {
        let format = zetafill_cli::plan::format::Format::resolve(l.output.format, &l.output.output)
            .unwrap_or(zetafill_cli::plan::format::Format::Svg);
        let (run, draw) = zetafill_cli::plan::line::resolve_as(&l, format).unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        let (doc, halt) = zetafill_cli::cmd::line::compute(&run).unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        assert!(halt.is_none(), "{} halted", args_file.display());
        let bytes = zetafill_cli::cmd::line::render(&doc, format, &draw).unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        return (gallery().join(&l.output.output), bytes);
    }
    let a = parse_fill(&args);
    let format =
        zetafill_cli::plan::format::Format::resolve(a.output.format, &a.output.output).unwrap_or(zetafill_cli::plan::format::Format::Svg);
    let (run, draw) = zetafill_cli::plan::fill::resolve_as(&a, format).unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
    let (doc, halt) = zetafill_cli::cmd::fill::compute(&run).unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
    assert!(halt.is_none(), "{} halted", args_file.display());
    let bytes = zetafill_cli::cmd::fill::render(&doc, format, &draw).unwrap_or_default();
    (gallery().join(&a.output.output), bytes)
}

#[test]
fn gallery_pictures_are_what_the_tool_writes() {
    let regenerate = std::env::var_os("ZETAFILL_REGENERATE").is_some();
    let mut entries: Vec<PathBuf> = std::fs::read_dir(gallery())
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    entries.retain(|p| p.extension().is_some_and(|e| e == "args"));
    entries.sort();
    assert!(entries.len() >= 3, "gallery has {} parameter files", entries.len());
    for args_file in entries {
        let (out, bytes) = render(&args_file);
        if regenerate {
            std::fs::write(&out, &bytes).unwrap_or_else(|e| panic!("{}: {e}", out.display()));
            continue;
        }
        let committed = std::fs::read(&out).unwrap_or_default();
        if let Some(at) = first_difference(&committed, &bytes) {
            panic!(
                "{} differs from what {} writes now (first difference at byte {at}); rerun with ZETAFILL_REGENERATE=1 if intended",
                out.display(),
                args_file.display()
            );
        }
    }
}

#[test]
fn comparison_detects_a_changed_byte() {
    let a = b"<svg>abc</svg>".to_vec();
    let mut b = a.clone();
    b[6] = b'x';
    assert_eq!(first_difference(&a, &b), Some(6));
    assert_eq!(first_difference(&a, &a[..10]), Some(10));
    assert_eq!(first_difference(&a, &a), None);
}
