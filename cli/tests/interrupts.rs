//! Interrupts while an output is written (docs/cli.md, Files: a failure or Ctrl-C never leaves a
//! truncated file and never destroys an existing one).
//!
//! Bug pinned here: Ctrl-C while the output was written left its temporary file,
//! `.zetafill-XXXXXX.tmp` (megabytes), in the output folder. Now SIGINT, SIGTERM and SIGHUP
//! remove it, the process still ends by the signal, and the old output survives.
//!
//! The signal is sent the moment the temporary file shows in the folder. The write takes a few
//! milliseconds, so a run may finish before the signal lands; the test repeats until enough
//! runs were interrupted with the file present, and checks every run, interrupted or not.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]
#![cfg(unix)]

mod common;

use common::*;
use std::os::unix::process::ExitStatusExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const OLD: &[u8] = b"the old output, which must survive\n";

fn temporaries(dir: &Path) -> Vec<PathBuf> {
    listing(dir)
        .into_iter()
        .filter(|p| {
            let name = p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            name.starts_with(".zetafill-") && name.ends_with(".tmp")
        })
        .collect()
}

/// Whether the output's temporary file has bytes in it (the one `-o` checks the folder with
/// before the work is empty): the write is under way.
fn writing(dir: &Path) -> bool {
    temporaries(dir).iter().any(|p| std::fs::metadata(p).is_ok_and(|m| m.len() > 0))
}

/// One run of a large fill into `out.json` over the old file, with `signal` sent as soon as a
/// temporary file appears. Returns whether the signal ended the process.
fn interrupted_run(dir: &Path, signal: &str, signo: i32) -> bool {
    std::fs::write(dir.join("out.json"), OLD).unwrap_or_else(|e| panic!("{e}"));
    let mut child = Command::new(env!("CARGO_BIN_EXE_zetafill"))
        .args(["fill", "--count", "100000", "--seed", "5", "-o", "out.json"])
        .current_dir(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot run zetafill: {e}"));
    let deadline = Instant::now() + Duration::from_secs(120);
    let mut sent = false;
    let status = loop {
        if let Some(s) = child.try_wait().unwrap_or_else(|e| panic!("{e}")) {
            break s;
        }
        if !sent && writing(dir) {
            let ok = Command::new("kill")
                .args([signal, &child.id().to_string()])
                .status()
                .is_ok_and(|s| s.success());
            assert!(ok, "kill {signal} failed");
            sent = true;
        }
        assert!(Instant::now() < deadline, "the fill did not end");
    };
    let left = temporaries(dir);
    assert!(left.is_empty(), "{signal}: temporary files left behind: {left:?}");
    let now = read(&dir.join("out.json"));
    if status.signal() == Some(signo) {
        // Before the rename the old output stays; a signal that lands after it (while the
        // process ends) finds the new output complete. Never anything in between.
        if now == OLD {
            return true;
        }
        assert!(
            now.starts_with(b"{") && now.ends_with(b"}\n"),
            "{signal}: the output is neither the old one nor complete"
        );
        parse_json(&now);
        false
    } else {
        assert_eq!(status.code(), Some(0), "{signal}: not interrupted, so a normal end: {status:?}");
        assert!(now.starts_with(b"{"), "{signal}: the new output is complete JSON");
        parse_json(&now);
        false
    }
}

fn interrupts_leave_nothing(signal: &str, signo: i32) {
    let dir = tmp();
    let mut caught = 0;
    for _ in 0..40 {
        if interrupted_run(dir.path(), signal, signo) {
            caught += 1;
            if caught == 3 {
                return;
            }
        }
    }
    panic!("{signal}: only {caught} of 40 runs were interrupted while the temporary file existed");
}

#[test]
fn ctrl_c_during_the_write_removes_the_temporary_file() {
    interrupts_leave_nothing("-INT", 2);
}

#[test]
fn sigterm_during_the_write_removes_the_temporary_file() {
    interrupts_leave_nothing("-TERM", 15);
}

/// The control: without the handler the same sequence leaves the file. A process that is
/// killed by SIGKILL runs no handler, so its temporary file stays; this shows the checker
/// above sees a leftover file when there is one.
#[test]
fn the_checker_sees_a_file_left_by_sigkill() {
    let dir = tmp();
    let d = dir.path();
    for _ in 0..40 {
        std::fs::write(d.join("out.json"), OLD).unwrap_or_else(|e| panic!("{e}"));
        let mut child = Command::new(env!("CARGO_BIN_EXE_zetafill"))
            .args(["fill", "--count", "100000", "--seed", "5", "-o", "out.json"])
            .current_dir(d)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap_or_else(|e| panic!("cannot run zetafill: {e}"));
        let status = loop {
            if let Some(s) = child.try_wait().unwrap_or_else(|e| panic!("{e}")) {
                break s;
            }
            if writing(d) {
                let _ = child.kill();
                break child.wait().unwrap_or_else(|e| panic!("{e}"));
            }
        };
        if status.signal() == Some(9) && !temporaries(d).is_empty() {
            assert!(read(&d.join("out.json")) == OLD, "the old output stays");
            return;
        }
    }
    panic!("SIGKILL never caught a temporary file: the checker cannot be shown to fail");
}

/// A streamed output is interrupted too: SIGINT in the middle of a 1 GB STL, written one solid
/// at a time into its temporary file, removes that file and leaves the old output. The write
/// takes seconds, so the signal is sent once the temporary file holds a few MB (well before
/// its end), and a run or two is enough.
#[test]
fn ctrl_c_in_the_middle_of_a_streamed_mesh_removes_the_temporary_file() {
    let dir = tmp();
    let d = dir.path();
    // 80 spheres of 512 * 510 triangles: 1.04 GB.
    let full = 84 + 50 * 80 * 512 * 510;
    for _ in 0..3 {
        std::fs::write(d.join("out.stl"), OLD).unwrap_or_else(|e| panic!("{e}"));
        let mut child = Command::new(env!("CARGO_BIN_EXE_zetafill"))
            .args(["space", "-q", "--count", "80", "--segments", "512", "-o", "out.stl"])
            .current_dir(d)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap_or_else(|e| panic!("cannot run zetafill: {e}"));
        let deadline = Instant::now() + Duration::from_secs(300);
        let mut part = None;
        let status = loop {
            if let Some(s) = child.try_wait().unwrap_or_else(|e| panic!("{e}")) {
                break s;
            }
            let grown = temporaries(d)
                .iter()
                .filter_map(|p| std::fs::metadata(p).ok())
                .map(|m| m.len())
                .max();
            if part.is_none() && grown.is_some_and(|n| n > 4 << 20) {
                let ok = Command::new("kill")
                    .args(["-INT", &child.id().to_string()])
                    .status()
                    .is_ok_and(|s| s.success());
                assert!(ok, "kill -INT failed");
                part = grown;
            }
            assert!(Instant::now() < deadline, "the write did not end");
            std::thread::sleep(Duration::from_millis(2));
        };
        let left = temporaries(d);
        assert!(left.is_empty(), "temporary files left behind: {left:?}");
        let len = std::fs::metadata(d.join("out.stl")).map(|m| m.len()).ok();
        if status.signal() == Some(2) && part.is_some_and(|n| n < full) {
            assert!(
                read(&d.join("out.stl")) == OLD,
                "the old output survives a streamed write cut short"
            );
            return;
        }
        // Not cut short (the signal came late): the old output or the complete new one.
        assert!(len == Some(full) || read(&d.join("out.stl")) == OLD, "{status:?}: {len:?} bytes");
    }
    panic!("no run was interrupted while the mesh was being written");
}
