//! The formats beyond SVG/JSON/CSV (PNG preview, digest line) and the output file's mode.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

mod common;

use common::*;

const PNG_SIG: &[u8] = b"\x89PNG\r\n\x1a\n";

/// Width and height from a PNG's IHDR chunk.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert!(bytes.starts_with(PNG_SIG), "not a PNG");
    assert_eq!(bytes.get(12..16), Some(&b"IHDR"[..]), "IHDR first");
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    (be(16), be(20))
}

#[test]
fn png_preview_has_the_page_size_at_the_dpi() {
    let dir = tmp();
    let d = dir.path();
    let base = ["--shape", "circle", "--region", "rect:100:80", "--count", "60", "--seed", "4"];
    let a = fill_to(d, "a.png", &base);
    assert_eq!(png_size(&a), (378, 303), "100 x 80 mm at 96 dpi");
    let b = fill_to(d, "b.png", &base);
    assert_eq!(a, b, "PNG reruns are byte-identical");
    let hi = fill_to(d, "hi.png", &[&base[..], &["--dpi", "150"]].concat());
    assert_eq!(png_size(&hi), (591, 473), "100 x 80 mm at 150 dpi");
    let other = fill_to(
        d,
        "c.png",
        &["--shape", "circle", "--region", "rect:100:80", "--count", "60", "--seed", "5"],
    );
    assert_ne!(a, other, "another seed gives another picture");
    let o = zf_ok(d, &[&["fill"][..], &base[..], &["-o", "-", "--format", "png"]].concat());
    assert_eq!(o.stdout, a, "PNG on stdout");
}

#[test]
fn png_bad_dpi() {
    for (dpi, flag) in [("0", "--dpi"), ("nan", "--dpi"), ("1e7", "--dpi")] {
        let dir = tmp();
        let d = dir.path();
        std::fs::write(d.join("x.png"), b"keep").unwrap_or_else(|e| panic!("{e}"));
        let o = zf(d, &["fill", "--region", "rect:100:80", "--count", "5", "--dpi", dpi, "-o", "x.png"]);
        assert_eq!(o.code, 2, "--dpi {dpi}: {}", o.stderr);
        assert!(names_flag(&o.stderr, flag), "--dpi {dpi}: {}", o.stderr);
        assert_eq!(read(&d.join("x.png")), b"keep");
        assert_eq!(listing(d).len(), 1);
    }
}

#[test]
fn digest_line() {
    let dir = tmp();
    let d = dir.path();
    let base = [
        "fill",
        "--shape",
        "square",
        "--region",
        "rect:100:80",
        "--count",
        "80",
        "--seed",
        "6",
        "--format",
        "digest",
    ];
    let a = zf_ok(d, &[&base[..], &["-o", "-"]].concat()).stdout;
    let text = String::from_utf8_lossy(&a).into_owned();
    let (count, hex) = text
        .trim_end_matches('\n')
        .split_once(' ')
        .unwrap_or_else(|| panic!("digest line: {text:?}"));
    assert_eq!(count, "80");
    assert_eq!(hex.len(), 16);
    assert!(hex.chars().all(|c| c.is_ascii_hexdigit() && !c.is_ascii_uppercase()), "{hex}");
    assert_eq!(text.lines().count(), 1);
    // Same run, same line; into a file too; another seed, another digest.
    assert_eq!(zf_ok(d, &[&base[..], &["-o", "-"]].concat()).stdout, a);
    zf_ok(d, &[&base[..], &["-o", "d.txt"]].concat());
    assert_eq!(read(&d.join("d.txt")), a);
    let mut other = base.to_vec();
    other[8] = "7";
    other.extend_from_slice(&["-o", "-"]);
    assert_ne!(zf_ok(d, &other).stdout, a);
}

#[cfg(unix)]
#[test]
fn output_mode_is_0644_or_kept() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tmp();
    let d = dir.path();
    let args = ["--region", "rect:100:80", "--count", "10"];
    fill_to(d, "new.json", &args);
    let mode = |p: &str| std::fs::metadata(d.join(p)).map(|m| m.permissions().mode() & 0o7777).unwrap_or(0);
    assert_eq!(mode("new.json"), 0o644, "a new output file");
    std::fs::write(d.join("old.json"), b"x").unwrap_or_else(|e| panic!("{e}"));
    std::fs::set_permissions(d.join("old.json"), std::fs::Permissions::from_mode(0o600)).unwrap_or_else(|e| panic!("{e}"));
    let bytes = fill_to(d, "old.json", &args);
    assert_eq!(mode("old.json"), 0o600, "a replaced file keeps its mode");
    assert_eq!(bytes, read(&d.join("new.json")));
}
