//! The one rule that keeps a user's files safe: no output is ever the same file as an input
//! of its command. Two guards hold it.
//!
//! - Before any work, [`refuse_overwrites`] compares every output a command names with every
//!   file it reads, as the command declares them (`plan::files`), each with the flag that
//!   names it. The same file means the same path once symbolic links are resolved, or the same
//!   device and inode (a hard link), so `-o link.png` pointing at the density picture is
//!   refused like `-o picture.png`.
//! - Every input the tool reads goes through [`crate::io::read`] or is noted with [`note_read`],
//!   which remembers its device and inode; [`was_read`] is asked again just before an output
//!   is put in place, so an input a command forgot to declare is still never replaced.
//!
//! Both refusals are usage errors (exit 2) and nothing is written.

use crate::error::CliError;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The files a command names: each output and each input with the flag that names it (`-o`
/// is `--output`; a positional input is named by its placeholder, such as `FILE`).
#[derive(Debug, Default)]
pub struct Files<'a> {
    /// What the command writes (`-` for standard output is left out).
    pub outputs: Vec<(&'static str, &'a Path)>,
    /// What the command reads.
    pub inputs: Vec<(&'static str, &'a Path)>,
}

impl<'a> Files<'a> {
    /// Adds an output unless it is standard output (`-`).
    pub fn output(&mut self, flag: &'static str, path: &'a Path) {
        if path.as_os_str() != "-" {
            self.outputs.push((flag, path));
        }
    }

    /// Adds an input.
    pub fn input(&mut self, flag: &'static str, path: &'a Path) {
        self.inputs.push((flag, path));
    }
}

/// Refuses, naming both flags, an output that is the same file as an input or as another
/// output of the same command.
pub fn refuse_overwrites(files: &Files) -> Result<(), CliError> {
    for (k, &(out_flag, out)) in files.outputs.iter().enumerate() {
        for &(in_flag, input) in &files.inputs {
            if same_file(out, input) {
                return Err(CliError::arg(
                    out_flag,
                    format!(
                        "'{}' is the file that {in_flag} reads ('{}'); an output never replaces an input: choose another output path",
                        out.display(),
                        input.display()
                    ),
                ));
            }
        }
        for &(other_flag, other) in files.outputs.iter().skip(k + 1) {
            if same_file(out, other) || out == other {
                return Err(CliError::arg(
                    other_flag,
                    format!(
                        "'{}' is also the file of {out_flag}; give each output its own path",
                        other.display()
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// Whether `a` and `b` are the same existing regular file: the same device and inode on Unix
/// (so hard and symbolic links are seen through), else the same path once links are resolved.
/// A device or a pipe is never the same file as anything: it is written into, not replaced,
/// so `--sites-from /dev/stdin -o /dev/stdout` on one terminal is no overwrite.
pub fn same_file(a: &Path, b: &Path) -> bool {
    if !std::fs::metadata(b).is_ok_and(|m| m.is_file()) {
        return false;
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
            return x.dev() == y.dev() && x.ino() == y.ino();
        }
    }
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

/// A file the tool has read: its identity, and the path it was read by.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Read {
    id: Option<Identity>,
    path: Option<PathBuf>,
}

/// Device, inode, length and modification time in nanoseconds: a file whose inode is used
/// again after another was deleted is not taken for it.
type Identity = (u64, u64, u64, i64);

/// Every input read so far by this process.
static READ: Mutex<Vec<Read>> = Mutex::new(Vec::new());

fn identity(m: &std::fs::Metadata) -> Option<Identity> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        Some((
            m.dev(),
            m.ino(),
            m.len(),
            m.mtime().saturating_mul(1_000_000_000).saturating_add(m.mtime_nsec()),
        ))
    }
    #[cfg(not(unix))]
    {
        let _ = m;
        None
    }
}

/// Notes that the file at `path`, whose metadata `m` is (of the open file, so a rename in
/// between cannot fool it), is an input of this run.
pub fn note_read_file(path: &Path, m: &std::fs::Metadata) {
    // Devices and pipes are read, never replaced: there is nothing to guard.
    if !m.is_file() {
        return;
    }
    let entry = Read {
        id: identity(m),
        path: std::fs::canonicalize(path).ok(),
    };
    let mut list = READ.lock().unwrap_or_else(|e| e.into_inner());
    if !list.contains(&entry) {
        list.push(entry);
    }
}

/// Forgets every input noted so far: a command starts with none.
pub fn forget_reads() {
    READ.lock().unwrap_or_else(|e| e.into_inner()).clear();
}

/// Notes that `path` is an input of this run (for a reader outside [`crate::io::read`]).
pub fn note_read(path: &Path) {
    if let Ok(m) = std::fs::metadata(path) {
        note_read_file(path, &m);
    }
}

/// Whether `path` names a file this run has read as an input.
pub fn was_read(path: &Path) -> bool {
    let list = READ.lock().unwrap_or_else(|e| e.into_inner());
    if list.is_empty() {
        return false;
    }
    let id = std::fs::metadata(path).ok().as_ref().and_then(identity);
    let canonical = std::fs::canonicalize(path).ok();
    list.iter()
        .any(|r| (id.is_some() && r.id == id) || (canonical.is_some() && r.path == canonical))
}

/// The refusal of an output that [`was_read`] as an input: a usage error naming `arg`.
pub fn refuse_read(arg: &str, path: &Path) -> Result<(), CliError> {
    if was_read(path) {
        return Err(CliError::arg(
            arg,
            format!(
                "'{}' is a file this command read as an input; an output never replaces an input: choose another output path (nothing was written)",
                path.display()
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_and_paths_name_the_same_file() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let d = dir.path();
        let pic = d.join("pic.png");
        std::fs::write(&pic, b"x").unwrap_or_else(|e| panic!("{e}"));
        assert!(same_file(&pic, &d.join("./pic.png")));
        assert!(!same_file(&pic, &d.join("new.png")));
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink("pic.png", d.join("link.png")).unwrap_or_else(|e| panic!("{e}"));
            std::fs::hard_link(&pic, d.join("hard.png")).unwrap_or_else(|e| panic!("{e}"));
            assert!(same_file(&d.join("link.png"), &pic));
            assert!(same_file(&d.join("hard.png"), &pic));
        }
        let mut f = Files::default();
        f.output("--output", &pic);
        f.input("--machine", Path::new("/nonexistent/m.toml"));
        assert!(refuse_overwrites(&f).is_ok());
        // A device is written into, never replaced: no overwrite.
        let mut g = Files::default();
        g.output("--output", Path::new("/dev/null"));
        g.input("--sites-from", Path::new("/dev/null"));
        assert!(refuse_overwrites(&g).is_ok());
        f.input("--density", &pic);
        let e = refuse_overwrites(&f).err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.starts_with("--output: ") && e.contains("--density"), "{e}");
    }

    #[test]
    fn a_read_input_is_remembered_by_identity() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let d = dir.path();
        let a = d.join("a.json");
        std::fs::write(&a, b"{}").unwrap_or_else(|e| panic!("{e}"));
        assert!(!was_read(&a), "the control: not read yet");
        note_read(&a);
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink("a.json", d.join("l.json")).unwrap_or_else(|e| panic!("{e}"));
            assert!(was_read(&d.join("l.json")));
        }
        let e = refuse_read("--output", &a).err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.starts_with("--output: "), "{e}");
        assert!(!was_read(&d.join("b.json")));
        // A device is never guarded (it is written into, not replaced).
        note_read(Path::new("/dev/null"));
        assert!(!was_read(Path::new("/dev/null")));
    }
}
