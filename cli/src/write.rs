//! Output destinations: a file written atomically (a temporary file in the same folder,
//! renamed into place), or standard output for `-`. A failure or Ctrl-C never leaves a
//! truncated file and never destroys an existing one.

use crate::error::CliError;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Where output goes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Dest {
    /// Standard output.
    Stdout,
    /// A file path.
    File(PathBuf),
}

impl Dest {
    /// Parses `-o`: `-` is standard output.
    pub fn parse(s: &Path) -> Dest {
        if s.as_os_str() == "-" {
            Dest::Stdout
        } else {
            Dest::File(s.to_path_buf())
        }
    }

    /// Checks before any work that the destination can be written: not a directory, its
    /// folder exists, and it is none of `inputs`.
    pub fn check(&self, arg: &str, inputs: &[&Path]) -> Result<(), CliError> {
        let Dest::File(p) = self else { return Ok(()) };
        if p.is_dir() {
            return Err(CliError::arg(arg, format!("'{}' is a directory; give a file name", p.display())));
        }
        let dir = parent_dir(p);
        if !dir.is_dir() {
            return Err(CliError::arg(arg, format!("the folder '{}' does not exist", dir.display())));
        }
        for i in inputs {
            if same_file(p, i) {
                return Err(CliError::arg(
                    arg,
                    format!("'{}' is also an input; choose another output path", p.display()),
                ));
            }
        }
        Ok(())
    }

    /// Writes `bytes` (atomically for a file).
    pub fn write(&self, bytes: &[u8]) -> Result<(), CliError> {
        match self {
            Dest::Stdout => {
                let mut out = std::io::stdout().lock();
                out.write_all(bytes)
                    .and_then(|_| out.flush())
                    .map_err(|e| CliError::Io(format!("writing to standard output: {e}")))
            }
            Dest::File(p) => write_atomic(p, bytes),
        }
    }
}

fn parent_dir(p: &Path) -> PathBuf {
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

/// Writes `bytes` to a temporary file beside `path`, syncs it, and renames it over `path`.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    let dir = parent_dir(path);
    let io = |what: &str, e: std::io::Error| CliError::Io(format!("{what} '{}': {e}", path.display()));
    let mut tmp = tempfile::Builder::new()
        .prefix(".zetafill-")
        .suffix(".tmp")
        .tempfile_in(&dir)
        .map_err(|e| io("cannot create a temporary file for", e))?;
    tmp.write_all(bytes).map_err(|e| io("cannot write", e))?;
    // Temporary files are private (0600); the output gets the mode a new file would get
    // (0644 here) or keeps the mode of the file it replaces.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(path).map(|m| m.permissions().mode() & 0o7777).unwrap_or(0o644);
        std::fs::set_permissions(tmp.path(), std::fs::Permissions::from_mode(mode)).map_err(|e| io("cannot set permissions of", e))?;
    }
    tmp.as_file().sync_all().map_err(|e| io("cannot sync", e))?;
    tmp.persist(path).map_err(|e| io("cannot rename into", e.error))?;
    Ok(())
}
