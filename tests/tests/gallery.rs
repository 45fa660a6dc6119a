//! Reference outputs: every `examples/gallery/NAME.args` (a `fill`, `line`, `tile`, `territory` or `space` command)
//! run in process must write exactly the committed picture. An output too large to commit (the STL for printing) is
//! pinned instead by `OUTPUT.sha256` beside the `.args` (`sha256sum` format, so `sha256sum -c` checks a file made on
//! the command line). Set `ZETAFILL_REGENERATE=1` to rewrite the pictures and pins after an intended change (and look
//! at them before committing).
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};
use zetafill_tests::parse_fill;

/// Outputs kept as a SHA-256 pin rather than committed: by extension.
const PINNED: &[&str] = &["stl"];

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
    // A picture or an SVG (a region or a motif) named by a relative path is found from the
    // gallery folder, where the commands run.
    args.extend(text.split_whitespace().map(|a| {
        for prefix in ["image:", "svg:"] {
            if let Some(rest) = a.strip_prefix(prefix).filter(|r| !r.starts_with('/')) {
                return format!("{prefix}{}", gallery().join(rest).display());
            }
        }
        a.to_string()
    }));
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
    if let zetafill_cli::Command::Space(s) = command {
        let format = zetafill_cli::plan::format::SpaceFormat::resolve(s.output.format, &s.output.output)
            .unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        let (run, draw) = zetafill_cli::plan::space::resolve_as(&s, format).unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        let (doc, halt) = zetafill_cli::cmd::space::compute(&run).unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        assert!(halt.is_none(), "{} halted", args_file.display());
        let bytes = zetafill_cli::cmd::space::render(&doc, format, &draw).unwrap_or_else(|e| panic!("{}: {e}", args_file.display()));
        return (gallery().join(&s.output.output), bytes);
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
    // Rendered on two threads, every other file each (the runs share no state), then checked
    // in order.
    let rendered: Vec<(PathBuf, (PathBuf, Vec<u8>))> = std::thread::scope(|s| {
        let odd = s.spawn(|| {
            entries
                .iter()
                .skip(1)
                .step_by(2)
                .map(|f| (f.clone(), render(f)))
                .collect::<Vec<_>>()
        });
        let even: Vec<_> = entries.iter().step_by(2).map(|f| (f.clone(), render(f))).collect();
        let odd = odd.join().unwrap_or_else(|_| panic!("a render thread failed"));
        let mut all = Vec::with_capacity(entries.len());
        let mut odd = odd.into_iter();
        for e in even {
            all.push(e);
            all.extend(odd.next());
        }
        all
    });
    for (args_file, (out, bytes)) in rendered {
        let (out, bytes) = if out.extension().is_some_and(|e| PINNED.iter().any(|p| e == *p)) {
            pin(&out, &bytes)
        } else {
            (out, bytes)
        };
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

/// The picture `density-image.args` follows, `density-source.png`: a dark, soft-edged letter Z
/// on white, 240 x 240 pixels, made here so that the gallery needs no download.
fn density_source() -> Vec<u8> {
    let (w, h) = (240u32, 240u32);
    // The strokes of the Z, as segments of a pen 36 pixels wide with 6 pixels of soft edge.
    let strokes = [
        ((40.0, 50.0), (200.0, 50.0)),
        ((200.0, 50.0), (40.0, 190.0)),
        ((40.0, 190.0), (200.0, 190.0)),
    ];
    let dist = |p: (f64, f64), a: (f64, f64), b: (f64, f64)| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
        (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
    };
    let mut data = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let p = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            let d = strokes.iter().map(|&(a, b)| dist(p, a, b)).fold(f64::MAX, f64::min);
            let light = ((d - 18.0) / 6.0).clamp(0.0, 1.0);
            data.push((255.0 * light).round() as u8);
        }
    }
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, w, h);
    enc.set_color(png::ColorType::Grayscale);
    enc.set_depth(png::BitDepth::Eight);
    enc.write_header()
        .and_then(|mut wr| wr.write_image_data(&data))
        .unwrap_or_else(|e| panic!("{e}"));
    out
}

/// The committed `density-source.png` is the picture [`density_source`] makes (rewritten with
/// `ZETAFILL_REGENERATE=1`); the gallery test fills by it.
#[test]
fn the_density_source_is_made_by_the_test() {
    let path = gallery().join("density-source.png");
    let made = density_source();
    if std::env::var_os("ZETAFILL_REGENERATE").is_some() {
        std::fs::write(&path, &made).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
    assert_eq!(first_difference(&std::fs::read(&path).unwrap_or_default(), &made), None);
}

/// The pin file of `out` and its text: `HEX  NAME` and a newline, as `sha256sum` writes it.
fn pin(out: &Path, bytes: &[u8]) -> (PathBuf, Vec<u8>) {
    let name = out.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let hex: String = Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect();
    (
        out.with_file_name(format!("{name}.sha256")),
        format!("{hex}  {name}\n").into_bytes(),
    )
}

#[test]
fn a_pin_is_sha256sum_of_the_bytes() {
    let (path, text) = pin(Path::new("g/a.stl"), b"abc");
    assert_eq!(path, Path::new("g/a.stl.sha256"));
    let want = "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad  a.stl\n";
    assert_eq!(String::from_utf8_lossy(&text), want);
    assert_ne!(pin(Path::new("a.stl"), b"abd").1, text);
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
