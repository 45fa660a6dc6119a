//! Outputs are streamed into their file, and one larger than `--max-output-size` is refused
//! before anything is written.
//!
//! Bug pinned here: STL and OBJ were built whole in memory. `space
//! --count 300 --segments 1024 -o out.stl` (a 15.7 GB mesh) under a 4 GB address-space limit
//! aborted on a failed 6.7 GB allocation (SIGABRT, exit 134), and without a limit grew towards
//! ~100 GB; at the defaults, 10^5 spheres held the whole 2.6 GB file in memory. Now the file is
//! written one solid at a time, and a mesh above the limit (4 GiB by default) is a usage error
//! (exit 2) that says how large it would have been.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
#![cfg(unix)]

mod common;

use common::*;
use std::path::Path;
use std::process::Command;

const OLD: &[u8] = b"the old output, which must survive\n";

/// Runs `zetafill ARGS` in `dir` with its address space limited to `kib` KiB (`ulimit -v`).
fn zf_limited(dir: &Path, kib: u64, args: &[&str]) -> Out {
    let out = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v \"$0\" && exec \"$@\"")
        .arg(kib.to_string())
        .arg(env!("CARGO_BIN_EXE_zetafill"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| panic!("cannot run sh: {e}"));
    Out {
        code: out.status.code().unwrap_or(-1),
        stdout: out.stdout,
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// The files the tool left in `dir` besides `keep`.
fn others(dir: &Path, keep: &[&str]) -> Vec<String> {
    listing(dir)
        .into_iter()
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .filter(|n| !keep.contains(&n.as_str()))
        .collect()
}

#[test]
fn a_mesh_larger_than_memory_is_refused_not_aborted() {
    let dir = tmp();
    let d = dir.path();
    let o = zf_limited(
        d,
        4_000_000,
        &["space", "-q", "--count", "300", "--segments", "1024", "-o", "out.stl"],
    );
    assert_ne!(o.code, 134, "aborted: {}", o.stderr);
    assert_eq!(o.code, 2, "{}", o.stderr);
    // 300 spheres of 1024 * 1022 triangles: 84 + 50 * 313958400 bytes.
    assert!(
        o.stderr.contains("--max-output-size") && o.stderr.contains("15697920084 bytes"),
        "{}",
        o.stderr
    );
    assert!(
        o.stderr.contains("--segments") && o.stderr.contains("--count"),
        "says what to change: {}",
        o.stderr
    );
    assert!(others(d, &[]).is_empty(), "nothing written: {:?}", others(d, &[]));
}

#[test]
fn a_streamed_mesh_fits_an_address_space_smaller_than_the_file() {
    let dir = tmp();
    let d = dir.path();
    // 100 spheres of 65024 triangles: a 325 MB file, written under a 200 MB address space
    // (the fill itself needs a few MB).
    let args = ["space", "-q", "--count", "100", "--segments", "256", "--n-offset", "2"];
    let o = zf_limited(d, 200_000, &[&args[..], &["-o", "limited.stl"]].concat());
    assert_eq!(o.code, 0, "{}", o.stderr);
    zf_ok(d, &[&args[..], &["-o", "free.stl"]].concat());
    let (a, b) = (read(&d.join("limited.stl")), read(&d.join("free.stl")));
    assert_eq!(a.len(), 84 + 50 * 100 * 65024);
    assert!(a == b, "the same bytes with and without the limit");
}

/// The exact size of the file `args` writes at `name` (written without a limit).
fn size_of(dir: &Path, args: &[&str], name: &str) -> u64 {
    zf_ok(dir, &[args, &["-o", name]].concat());
    let n = read(&dir.join(name)).len() as u64;
    std::fs::remove_file(dir.join(name)).unwrap_or_else(|e| panic!("{e}"));
    n
}

/// `args -o out.EXT` is refused under a limit one byte below its size, names the flag and the
/// exact size, writes nothing and leaves the old file; at exactly its size it is written.
fn refused_just_above(dir: &Path, args: &[&str], ext: &str) {
    let out = format!("out.{ext}");
    let size = size_of(dir, args, &format!("free.{ext}"));
    std::fs::write(dir.join(&out), OLD).unwrap_or_else(|e| panic!("{e}"));
    let below = (size - 1).to_string();
    let o = zf(dir, &[args, &["--max-output-size", &below, "-o", &out]].concat());
    assert_eq!(o.code, 2, "{args:?} {ext}: {}", o.stderr);
    assert!(
        o.stderr.contains("--max-output-size") && o.stderr.contains(&format!("would be {size} bytes")),
        "{args:?} {ext}: {}",
        o.stderr
    );
    assert!(read(&dir.join(&out)) == OLD, "{ext}: the old file is untouched");
    assert_eq!(others(dir, &[&out]), Vec::<String>::new(), "{ext}: no temporary file");
    let exact = size.to_string();
    zf_ok(dir, &[args, &["--max-output-size", &exact, "-o", &out]].concat());
    assert_eq!(read(&dir.join(&out)).len() as u64, size, "{ext}: written at the limit");
    std::fs::remove_file(dir.join(&out)).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn every_space_format_is_refused_at_its_exact_size() {
    let dir = tmp();
    let args = [
        "space",
        "-q",
        "--count",
        "30",
        "--shape",
        "mix:sphere,torus:0.4,cube",
        "--n-offset",
        "3",
    ];
    for ext in ["stl", "obj", "json", "csv", "glb", "digest"] {
        let args = [&args[..], &["--format", ext]].concat();
        refused_just_above(dir.path(), &args, ext);
    }
}

#[test]
fn every_fill_and_line_format_is_refused_at_its_exact_size() {
    let dir = tmp();
    let fill = ["fill", "--count", "120", "--shape", "mix:circle,polygon:6", "--seed", "4"];
    for ext in ["svg", "json", "csv", "gcode", "png"] {
        refused_just_above(dir.path(), &fill, ext);
    }
    let line = ["line", "--count", "80", "--seed", "4"];
    for ext in ["svg", "json", "csv"] {
        refused_just_above(dir.path(), &line, ext);
    }
}

#[test]
fn standard_output_is_streamed_and_limited_too() {
    let dir = tmp();
    let d = dir.path();
    let args = ["space", "-q", "--count", "20", "--format", "stl", "--seed", "5"];
    zf_ok(d, &[&args[..], &["-o", "out.stl"]].concat());
    let o = zf_ok(d, &[&args[..], &["-o", "-"]].concat());
    assert!(o.stdout == read(&d.join("out.stl")), "the same bytes on standard output");
    let o = zf(d, &[&args[..], &["--max-output-size", "1K", "-o", "-"]].concat());
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(o.stdout.is_empty(), "nothing written to standard output");
}

#[test]
fn a_count_that_alone_makes_the_mesh_too_large_is_refused_before_the_fill() {
    let dir = tmp();
    let d = dir.path();
    std::fs::write(d.join("out.stl"), OLD).unwrap_or_else(|e| panic!("{e}"));
    // A million spheres: a fill of minutes, refused at once.
    let o = zf(d, &["space", "-q", "--count", "1000000", "-o", "out.stl"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
    // 1000000 spheres of 24 * 22 triangles.
    assert!(
        o.stderr.contains("26400000084 bytes") && o.stderr.contains("4294967296 bytes"),
        "{}",
        o.stderr
    );
    assert!(read(&d.join("out.stl")) == OLD);
    let o = zf(d, &["space", "--count", "10", "--max-output-size", "0", "-o", "out.stl"]);
    assert_eq!(o.code, 2, "a zero limit is refused: {}", o.stderr);
    assert!(o.stderr.contains("max-output-size"), "{}", o.stderr);
}
