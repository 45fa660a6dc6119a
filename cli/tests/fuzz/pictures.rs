//! Pictures (`--density image:FILE`, `--region mask:FILE`, `io::image`): arbitrary bytes
//! behind a PNG or JPEG signature, and mutations of valid pictures of every PNG colour type
//! and bit depth (bytes flipped, cut short, a header claiming other sizes with a correct
//! checksum). The decoder either gives a picture whose luminances are `width * height`
//! finite values in `[0, 1]`, or a readable error; the whole tool, given the file as a density
//! or a mask, exits 0, 2 or 3, never panics, and a refusal names its flag.

use crate::*;
use std::process::Command;

/// The CRC-32 of PNG chunks (polynomial 0xEDB88320), for headers rewritten with new sizes.
fn crc32(bytes: &[u8]) -> u32 {
    let mut c = !0u32;
    for &b in bytes {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 != 0 { 0xEDB8_8320 ^ (c >> 1) } else { c >> 1 };
        }
    }
    !c
}

/// A valid PNG of `w x h` pixels of a colour type and bit depth, with pixel bytes from `seed`.
fn png_bytes(w: u32, h: u32, colour: png::ColorType, depth: png::BitDepth, seed: u64) -> Vec<u8> {
    let channels = match colour {
        png::ColorType::Grayscale | png::ColorType::Indexed => 1,
        png::ColorType::GrayscaleAlpha => 2,
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
    };
    let bits = depth as usize;
    let row = (w as usize * channels * bits).div_ceil(8);
    let mut x = seed | 1;
    let data: Vec<u8> = (0..row * h as usize)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x as u8
        })
        .collect();
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, w, h);
        enc.set_color(colour);
        enc.set_depth(depth);
        if colour == png::ColorType::Indexed {
            enc.set_palette((0..(3usize << bits)).map(|k| (k * 37) as u8).collect::<Vec<u8>>());
        }
        let Ok(mut wr) = enc.write_header() else { return Vec::new() };
        let _ = wr.write_image_data(&data);
    }
    out
}

/// A valid picture (PNG of any legal colour type and depth, or JPEG), a few pixels across.
fn picture() -> impl Strategy<Value = Vec<u8>> {
    use png::{BitDepth as B, ColorType as C};
    let kinds = vec![
        (C::Grayscale, B::One),
        (C::Grayscale, B::Two),
        (C::Grayscale, B::Four),
        (C::Grayscale, B::Eight),
        (C::Grayscale, B::Sixteen),
        (C::Rgb, B::Eight),
        (C::Rgb, B::Sixteen),
        (C::Indexed, B::One),
        (C::Indexed, B::Four),
        (C::Indexed, B::Eight),
        (C::GrayscaleAlpha, B::Eight),
        (C::Rgba, B::Eight),
        (C::Rgba, B::Sixteen),
    ];
    prop_oneof![
        5 => (1u32..24, 1u32..24, select(kinds), any::<u64>()).prop_map(|(w, h, (c, d), s)| png_bytes(w, h, c, d, s)),
        1 => (1u16..24, 1u16..24, any::<u8>()).prop_map(|(w, h, v)| {
            let mut out = Vec::new();
            let data = vec![v; usize::from(w) * usize::from(h)];
            let _ = jpeg_encoder::Encoder::new(&mut out, 90).encode(&data, w, h, jpeg_encoder::ColorType::Luma);
            out
        }),
    ]
}

/// A hostile picture file: a valid one mutated, or noise behind a signature.
fn hostile_picture() -> impl Strategy<Value = Vec<u8>> {
    let sizes = select(vec![0u32, 1, 2, 3, 7, 255, 8000, 10_000, 65_535, 1 << 20, u32::MAX >> 1, u32::MAX]);
    prop_oneof![
        // Bytes flipped anywhere.
        3 => (picture(), prop::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..6)).prop_map(|(mut p, flips)| {
            if !p.is_empty() {
                for (i, v) in flips {
                    let k = i.index(p.len());
                    p[k] ^= v | 1;
                }
            }
            p
        }),
        // Cut short.
        2 => (picture(), any::<prop::sample::Index>()).prop_map(|(p, i)| p[..i.index(p.len().max(1)).min(p.len())].to_vec()),
        // A PNG header claiming other sizes, its checksum made right.
        3 => (picture(), sizes.clone(), sizes).prop_map(|(mut p, w, h)| {
            if p.starts_with(b"\x89PNG\r\n\x1a\n") && p.len() >= 33 {
                p[16..20].copy_from_slice(&w.to_be_bytes());
                p[20..24].copy_from_slice(&h.to_be_bytes());
                let crc = crc32(&p[12..29]);
                p[29..33].copy_from_slice(&crc.to_be_bytes());
            }
            p
        }),
        // Noise behind a signature.
        1 => (select(vec![&b"\x89PNG\r\n\x1a\n"[..], &[0xff, 0xd8, 0xff][..], &b""[..]]), prop::collection::vec(any::<u8>(), 0..300))
            .prop_map(|(sig, rest)| [sig, &rest[..]].concat()),
        1 => picture(),
    ]
}

/// The decoder on hostile pictures: a sound picture or a readable error, never a panic.
#[test]
fn pictures_decode_or_are_refused() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("p.png");
    let tally = Tally::new(&["decoded", "refused"]);
    fuzz("pictures", 1500, hostile_picture(), |bytes| {
        std::fs::write(&path, &bytes).map_err(|e| e.to_string())?;
        match zetafill_cli::io::image::read_grey(&path) {
            Ok(g) => {
                tally.add("decoded");
                if g.width == 0 || g.height == 0 || g.luma.len() != g.width * g.height {
                    return Err(format!("{} x {} with {} values", g.width, g.height, g.luma.len()));
                }
                if let Some(v) = g.luma.iter().find(|v| !(0.0..=1.0).contains(*v)) {
                    return Err(format!("a luminance of {v}"));
                }
                Ok(())
            }
            Err(e) => {
                tally.add("refused");
                readable(&e)
            }
        }
    });
    tally.report("pictures");
    assert!(tally.get("decoded") > 100 && tally.get("refused") > 100, "the generator drifted");
}

/// The tool on hostile pictures as a density and as a mask: exit 0, 2 or 3, a refusal names
/// its flag (or `--c` and `--n-offset`, for a mask too small for the first shape), and a
/// density fill that runs keeps its shapes in its rectangle.
#[test]
fn pictures_as_densities_and_masks_never_break_a_run() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let d = dir.path();
    let tally = Tally::new(&["filled", "refused"]);
    fuzz("picture_runs", 48, (hostile_picture(), any::<bool>()), |(bytes, as_mask)| {
        std::fs::write(d.join("p.png"), &bytes).map_err(|e| e.to_string())?;
        let (spec, flag) = if as_mask {
            ("--region=mask:p.png", "--region")
        } else {
            ("--density=image:p.png", "--density")
        };
        let o = Command::new(env!("CARGO_BIN_EXE_zetafill"))
            .args([
                "fill",
                "-q",
                "--count",
                "20",
                "--n-offset",
                "20",
                "--max-trials",
                "20000",
                spec,
                "-o",
                "-",
                "--format",
                "json",
            ])
            .current_dir(d)
            .output()
            .map_err(|e| e.to_string())?;
        let err = String::from_utf8_lossy(&o.stderr);
        match o.status.code() {
            Some(0) | Some(3) => {
                tally.add("filled");
                let doc: serde_json::Value = serde_json::from_slice(&o.stdout).map_err(|e| format!("{spec}: not JSON: {e}"))?;
                // The checker knows rectangles: a density fill's region (a mask's outline is
                // the region code's own, checked in `region_inputs.rs`).
                let inside = if as_mask {
                    Vec::new()
                } else {
                    common::geometry::check_inside(&doc)
                };
                if !inside.is_empty() {
                    return Err(format!("{spec}: {}", inside.join("; ")));
                }
                Ok(())
            }
            Some(2) => {
                tally.add("refused");
                let first = err.lines().next().unwrap_or("");
                if !first.contains(flag) && !first.contains("--c") && !first.contains("--n-offset") {
                    return Err(format!("{spec}: the refusal names no flag of it: {err}"));
                }
                readable(&err)
            }
            other => Err(format!("{spec}: exit {other:?}: {err}")),
        }
    });
    tally.report("picture runs");
    assert!(tally.get("filled") > 0 && tally.get("refused") > 0, "the generator drifted");
}
