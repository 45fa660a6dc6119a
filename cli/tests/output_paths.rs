//! Outputs that are not plain new files (docs/cli.md, What every subcommand shares): a symbolic link is
//! followed (its file is replaced atomically, the link stays), a character device or a named
//! pipe gets the bytes written straight into it and is never replaced.
//!
//! Bug pinned here: the temporary file + rename replaced whatever `-o` named, so `-o
//! /dev/null` (as root) replaced the device with a regular file, a FIFO was replaced, and
//! `-o link.svg` replaced the link instead of writing to its target.
//!
//! The device tests run first on private device nodes made with `mknod` in a temporary
//! folder (when allowed, as root), so a broken build replaces only those and never
//! `/dev/null`.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
#![cfg(unix)]

mod common;

use common::*;
use std::os::unix::fs::FileTypeExt;
use std::path::Path;
use std::process::{Command, Stdio};

const KEEP: &[u8] = b"existing content, must survive\n";
const FILL: [&str; 5] = ["fill", "--count", "30", "--format", "svg"];

/// `fill FILL -o out` in `dir`.
fn fill_into(dir: &Path, out: &str) -> Out {
    let mut a = FILL.to_vec();
    a.extend_from_slice(&["-o", out]);
    zf(dir, &a)
}

/// The bytes the fill writes (to a plain file).
fn expected(dir: &Path) -> Vec<u8> {
    let o = fill_into(dir, "reference.svg");
    assert_eq!(o.code, 0, "{}", o.stderr);
    let bytes = read(&dir.join("reference.svg"));
    std::fs::remove_file(dir.join("reference.svg")).unwrap_or_else(|e| panic!("rm: {e}"));
    bytes
}

fn file_type(p: &Path) -> std::fs::FileType {
    std::fs::symlink_metadata(p)
        .unwrap_or_else(|e| panic!("lstat {}: {e}", p.display()))
        .file_type()
}

fn symlink(target: &str, link: &Path) {
    std::os::unix::fs::symlink(target, link).unwrap_or_else(|e| panic!("symlink {}: {e}", link.display()));
}

/// A character device node `name` in `dir` (`mknod name c MAJOR MINOR`), if allowed and
/// usable (a `nodev` mount makes nodes that cannot be opened: they are removed).
fn mknod(dir: &Path, name: &str, major: u32, minor: u32) -> bool {
    let made = Command::new("mknod")
        .args([name, "c", &major.to_string(), &minor.to_string()])
        .current_dir(dir)
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if made && std::fs::OpenOptions::new().write(true).open(dir.join(name)).is_err() {
        let _ = std::fs::remove_file(dir.join(name));
        return false;
    }
    made
}

#[test]
fn symlinks_are_followed_and_survive() {
    let dir = tmp();
    let d = dir.path();
    let want = expected(d);
    std::fs::create_dir(d.join("sub")).unwrap_or_else(|e| panic!("mkdir: {e}"));
    std::fs::write(d.join("sub/target.svg"), KEEP).unwrap_or_else(|e| panic!("write: {e}"));
    symlink("sub/target.svg", &d.join("link.svg"));
    // A chain of two links.
    symlink("link.svg", &d.join("chain.svg"));
    // A dangling link: the file it names is created.
    symlink("sub/new.svg", &d.join("dangling.svg"));
    for link in ["link.svg", "chain.svg", "dangling.svg"] {
        let o = fill_into(d, link);
        assert_eq!(o.code, 0, "-o {link}: {}", o.stderr);
        assert!(file_type(&d.join(link)).is_symlink(), "-o {link} replaced the link");
    }
    assert_eq!(read(&d.join("sub/target.svg")), want, "the link's file holds the output");
    assert_eq!(read(&d.join("sub/new.svg")), want, "the dangling link's file was created");
    assert!(file_type(&d.join("sub/target.svg")).is_file());
    // Nothing else was left behind (no temporary files).
    assert_eq!(listing(&d.join("sub")), vec![d.join("sub/new.svg"), d.join("sub/target.svg")]);
    // A link into a missing folder, and a loop: exit 2 naming --output, links untouched.
    symlink("missing/x.svg", &d.join("nowhere.svg"));
    symlink("loop.svg", &d.join("loop.svg"));
    for link in ["nowhere.svg", "loop.svg"] {
        let o = fill_into(d, link);
        assert_eq!(o.code, 2, "-o {link}: exit {} ({})", o.code, o.stderr);
        assert!(names_flag(&o.stderr, "--output"), "{}", o.stderr);
        assert!(file_type(&d.join(link)).is_symlink());
    }
}

#[test]
fn a_named_pipe_gets_the_bytes_and_stays_a_pipe() {
    let dir = tmp();
    let d = dir.path();
    let want = expected(d);
    let st = Command::new("mkfifo")
        .arg("pipe.svg")
        .current_dir(d)
        .status()
        .unwrap_or_else(|e| panic!("mkfifo: {e}"));
    assert!(st.success(), "mkfifo failed");
    // The reader: a child, so that it can be killed if the pipe is never opened for writing.
    let mut reader = Command::new("cat")
        .arg("pipe.svg")
        .current_dir(d)
        .stdout(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cat: {e}"));
    let o = fill_into(d, "pipe.svg");
    let still_a_pipe = file_type(&d.join("pipe.svg")).is_fifo();
    if o.code != 0 || !still_a_pipe {
        let _ = reader.kill();
        let _ = reader.wait();
        panic!("-o pipe.svg: exit {}, still a pipe: {still_a_pipe} ({})", o.code, o.stderr);
    }
    let got = reader.wait_with_output().unwrap_or_else(|e| panic!("cat: {e}"));
    assert_eq!(got.stdout, want, "the reader got the output");
    assert_eq!(listing(d), vec![d.join("pipe.svg")], "no temporary file left");
}

/// A null device (a private node when allowed, then `/dev/null` itself) takes the output
/// and stays a device; a full device (private node only) is a write failure, exit 1, and
/// stays a device.
#[test]
fn character_devices_are_written_into_never_replaced() {
    let dir = tmp();
    let d = dir.path();
    let private_null = mknod(d, "null.svg", 1, 3);
    if private_null {
        let o = fill_into(d, "null.svg");
        assert_eq!(o.code, 0, "{}", o.stderr);
        assert!(file_type(&d.join("null.svg")).is_char_device(), "the null device was replaced");
    }
    if mknod(d, "full.svg", 1, 7) {
        let o = fill_into(d, "full.svg");
        assert_eq!(o.code, 1, "a full device: exit {} ({})", o.code, o.stderr);
        assert!(file_type(&d.join("full.svg")).is_char_device(), "the full device was replaced");
    }
    let mut names = listing(d);
    names.retain(|p| !["null.svg", "full.svg"].iter().any(|n| p.ends_with(n)));
    assert!(names.is_empty(), "left {names:?}");
    // Reached only when the private null device stayed a device, or when this process
    // cannot create files in /dev (and so could not replace /dev/null even when broken).
    let null = Path::new("/dev/null");
    let dev_locked = tempfile::tempfile_in("/dev").is_err();
    if file_type(null).is_char_device() && (private_null || dev_locked) {
        let o = fill_into(d, "/dev/null");
        assert_eq!(o.code, 0, "{}", o.stderr);
        assert!(file_type(null).is_char_device(), "/dev/null was replaced");
        // Through a link too.
        symlink("/dev/null", &d.join("link.svg"));
        assert_eq!(fill_into(d, "link.svg").code, 0);
        assert!(file_type(&d.join("link.svg")).is_symlink());
        assert!(file_type(null).is_char_device(), "/dev/null was replaced");
    }
}
