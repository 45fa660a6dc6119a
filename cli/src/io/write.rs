//! Output destinations: a file written atomically (a temporary file in the same folder,
//! renamed into place), a stream written straight into (a character device such as
//! `/dev/null`, or a named pipe), or standard output for `-`. An output is streamed into its
//! destination through a buffer as it is made ([`Dest::write_with`]; a size limit first: `cmd::write_output`),
//! so no file has to fit in memory. A failure or Ctrl-C never leaves
//! a truncated file and never destroys an existing one; a symbolic link is followed (the file
//! it points to is replaced, the link stays), and a device or pipe is never replaced.
//!
//! Interrupts: every temporary file is listed, from the moment it is created until it is
//! renamed into place or removed, in a list guarded by one lock. [`remove_temporaries_on_signal`]
//! starts a thread that, on SIGINT, SIGTERM or SIGHUP, takes the lock, removes every listed
//! file and ends the process by the same signal (so a shell sees an interrupted command). A
//! file is created and listed under the lock, and renamed and unlisted under it, so a signal
//! either finds it listed or finds it gone.

use crate::error::{io_error, CliError};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

/// The temporary files that exist now.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn temporaries() -> MutexGuard<'static, Vec<PathBuf>> {
    // A thread that panicked while holding the lock left a valid list: use it.
    TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner())
}

/// On SIGINT, SIGTERM or SIGHUP, removes every temporary file of an output being written,
/// then ends the process by that signal. Call once, from `main`; an existing output is never
/// touched (the temporary file had not been renamed over it).
pub fn remove_temporaries_on_signal() {
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
            return;
        };
        std::thread::spawn(move || {
            if let Some(sig) = signals.forever().next() {
                // Held until the process ends: no new temporary file can appear meanwhile.
                let list = temporaries();
                for p in list.iter() {
                    let _ = std::fs::remove_file(p);
                }
                let _ = signal_hook::low_level::emulate_default_handler(sig);
                std::process::exit(128 + sig);
            }
        });
    }
}

/// A temporary file beside an output, listed while it exists.
struct Temporary {
    file: Option<tempfile::NamedTempFile>,
    path: PathBuf,
}

impl Temporary {
    /// Creates a private (0600) temporary file in `dir` and lists it, under the lock.
    fn new_in(dir: &Path) -> std::io::Result<Temporary> {
        let mut list = temporaries();
        let file = tempfile::Builder::new().prefix(".zetafill-").suffix(".tmp").make_in(dir, |p| {
            let mut o = std::fs::OpenOptions::new();
            o.write(true).create_new(true);
            #[cfg(unix)]
            std::os::unix::fs::OpenOptionsExt::mode(&mut o, 0o600);
            let f = o.open(p)?;
            list.push(p.to_path_buf());
            Ok(f)
        })?;
        let path = file.path().to_path_buf();
        Ok(Temporary { file: Some(file), path })
    }

    fn file(&mut self) -> std::io::Result<&mut std::fs::File> {
        self.file
            .as_mut()
            .map(|f| f.as_file_mut())
            .ok_or_else(|| std::io::Error::other("the temporary file is gone"))
    }

    /// Renames the file over `path` and unlists it, under the lock.
    fn persist(mut self, path: &Path) -> std::io::Result<()> {
        let mut list = temporaries();
        let file = self
            .file
            .take()
            .ok_or_else(|| std::io::Error::other("the temporary file is gone"))?;
        let done = file.persist(path).map(drop).map_err(|e| e.error);
        // Renamed, or removed when the failed persist dropped it: either way no longer there.
        list.retain(|p| *p != self.path);
        done
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        let mut list = temporaries();
        // Removes the file (NamedTempFile's drop), then unlists it.
        self.file = None;
        list.retain(|p| *p != self.path);
    }
}

/// Where output goes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Dest {
    /// Standard output.
    Stdout,
    /// A file path.
    File(PathBuf),
}

/// What an output path names, symbolic links followed.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Target {
    /// A regular file or nothing yet: written atomically at this path, the end of any chain of
    /// symbolic links (so a link stays a link and its file gets the bytes).
    File(PathBuf),
    /// A character device or a named pipe: written straight into, since nothing can be
    /// renamed over it without destroying it (and atomicity means nothing there).
    // Only Unix tells these apart (the browser build has no file system at all).
    #[cfg_attr(not(unix), allow(dead_code))]
    Stream,
    /// A folder, a socket, a block device: never written.
    Other,
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

    /// Checks before any work that the destination can be written: not a directory, a file
    /// (or the file a symbolic link points to) whose folder exists and takes new files and
    /// which is not read-only, or else a character device or a named pipe. Every refusal is a
    /// usage error naming `arg`. That no output is an input is checked once for every command
    /// ([`crate::io::inputs::refuse_overwrites`]).
    pub fn check(&self, arg: &str) -> Result<(), CliError> {
        let Dest::File(p) = self else { return Ok(()) };
        if p.is_dir() {
            return Err(CliError::arg(arg, format!("'{}' is a directory; give a file name", p.display())));
        }
        if p.as_os_str().to_string_lossy().ends_with(std::path::MAIN_SEPARATOR) {
            return Err(CliError::arg(
                arg,
                format!("'{}' names a folder (it ends in a slash); give a file name", p.display()),
            ));
        }
        let target = resolve(p).map_err(|e| CliError::arg(arg, format!("cannot use '{}': {e}; choose another path", p.display())))?;
        match target {
            Target::Stream => Ok(()),
            Target::Other => Err(CliError::arg(
                arg,
                format!(
                    "'{}' is not a file, a character device or a named pipe; choose a file path",
                    p.display()
                ),
            )),
            Target::File(t) => {
                let dir = parent_dir(&t);
                if !dir.is_dir() {
                    return Err(CliError::arg(arg, format!("the folder '{}' does not exist", dir.display())));
                }
                if std::fs::metadata(&t).is_ok_and(|m| m.permissions().readonly()) {
                    return Err(CliError::arg(
                        arg,
                        format!("'{}' is read-only; make it writable or choose another path", p.display()),
                    ));
                }
                // The write puts a temporary file beside the output: try one now (it is
                // removed when dropped), so an unwritable folder is found before the work.
                temp_in(&dir).map(drop).map_err(|e| {
                    CliError::arg(
                        arg,
                        format!("cannot write in the folder '{}' ({e}); choose another path", dir.display()),
                    )
                })
            }
        }
    }

    /// Writes `bytes`: atomically for a file, straight into a device or a pipe.
    pub fn write(&self, bytes: &[u8]) -> Result<(), CliError> {
        self.write_with(|w| w.write_all(bytes).map_err(io_error))
    }

    /// Writes what `write` gives, through a buffer, as it comes: into a temporary file beside
    /// a file, renamed into place only when `write` succeeded (an error or an interrupt
    /// leaves the old file and no temporary one); straight into a device, a pipe or standard
    /// output. An I/O error is reported with the destination's name.
    pub fn write_with(&self, write: impl FnOnce(&mut dyn Write) -> Result<(), CliError>) -> Result<(), CliError> {
        match self {
            Dest::Stdout => {
                let out = std::io::stdout().lock();
                stream_into(out, write, |e| CliError::Io(format!("writing to standard output: {e}")))
            }
            Dest::File(p) => match resolve(p).map_err(|e| CliError::Io(format!("cannot use '{}': {e}", p.display())))? {
                Target::File(t) => {
                    // The last guard of the rule that no input is replaced, for an input a
                    // command did not declare.
                    crate::io::inputs::refuse_read("--output", &t)?;
                    write_atomic_with(&t, write)
                }
                Target::Stream => {
                    let f = std::fs::OpenOptions::new()
                        .write(true)
                        .open(p)
                        .map_err(|e| CliError::Io(format!("cannot open '{}': {e}", p.display())))?;
                    stream_into(f, write, |e| CliError::Io(format!("cannot write '{}': {e}", p.display())))
                }
                Target::Other => Err(CliError::Io(format!(
                    "'{}' is not a file, a character device or a named pipe; nothing written",
                    p.display()
                ))),
            },
        }
    }
}

/// A buffered writer that keeps the first I/O error it meets, so the destination can name
/// itself in the message whatever the output's writer made of the error.
struct Recording<W: Write> {
    inner: std::io::BufWriter<W>,
    error: Option<std::io::Error>,
}

impl<W: Write> Recording<W> {
    fn new(w: W) -> Recording<W> {
        Recording {
            inner: std::io::BufWriter::with_capacity(1 << 16, w),
            error: None,
        }
    }

    fn keep<T>(&mut self, r: std::io::Result<T>) -> std::io::Result<T> {
        r.map_err(|e| {
            let copy = std::io::Error::new(e.kind(), e.to_string());
            self.error.get_or_insert(e);
            copy
        })
    }

    /// The outcome of `write` followed by a flush, an I/O error reported by `io`.
    fn finish(mut self, done: Result<(), CliError>, io: impl Fn(std::io::Error) -> CliError) -> Result<std::io::BufWriter<W>, CliError> {
        let done = done.and_then(|()| {
            let r = self.inner.flush();
            self.keep(r).map_err(io_error)
        });
        match (done, self.error) {
            (Ok(()), _) => Ok(self.inner),
            (Err(_), Some(e)) => Err(io(e)),
            (Err(e), None) => Err(e),
        }
    }
}

impl<W: Write> Write for Recording<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let r = self.inner.write(buf);
        self.keep(r)
    }

    fn write_all(&mut self, buf: &[u8]) -> std::io::Result<()> {
        let r = self.inner.write_all(buf);
        self.keep(r)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        let r = self.inner.flush();
        self.keep(r)
    }
}

/// Runs `write` into `w` through a buffer and flushes it.
fn stream_into<W: Write>(
    w: W,
    write: impl FnOnce(&mut dyn Write) -> Result<(), CliError>,
    io: impl Fn(std::io::Error) -> CliError,
) -> Result<(), CliError> {
    let mut rec = Recording::new(w);
    let done = write(&mut rec);
    rec.finish(done, io).map(drop)
}

fn parent_dir(p: &Path) -> PathBuf {
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// What `p` names, following symbolic links.
fn resolve(p: &Path) -> std::io::Result<Target> {
    match std::fs::metadata(p) {
        Ok(m) => {
            let ft = m.file_type();
            if ft.is_file() {
                return Ok(Target::File(link_target(p)?));
            }
            #[cfg(unix)]
            {
                use std::os::unix::fs::FileTypeExt;
                if ft.is_char_device() || ft.is_fifo() {
                    return Ok(Target::Stream);
                }
            }
            Ok(Target::Other)
        }
        // A new file, perhaps at the end of a dangling symbolic link.
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Target::File(link_target(p)?)),
        Err(e) => Err(e),
    }
}

/// The path at the end of the chain of symbolic links that starts at `p` (`p` itself when it
/// is not a link). A relative link is taken from the folder that holds it.
fn link_target(p: &Path) -> std::io::Result<PathBuf> {
    let mut cur = p.to_path_buf();
    // Linux gives up after 40 links too (ELOOP).
    for _ in 0..40 {
        match std::fs::symlink_metadata(&cur) {
            Ok(m) if m.file_type().is_symlink() => {
                let next = std::fs::read_link(&cur)?;
                cur = if next.is_absolute() { next } else { parent_dir(&cur).join(next) };
            }
            Ok(_) => return Ok(cur),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(cur),
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::other("too many levels of symbolic links"))
}

fn temp_in(dir: &Path) -> std::io::Result<Temporary> {
    Temporary::new_in(dir)
}

/// Writes `bytes` to a temporary file beside `path`, syncs it, and renames it over `path`.
/// `path` must not be a symbolic link (the link would be replaced): [`Dest::write`] passes
/// the file a link points to.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    write_atomic_with(path, |w| w.write_all(bytes).map_err(io_error))
}

/// [`write_atomic`] of what `write` gives, streamed into the temporary file through a buffer;
/// nothing is renamed into place when `write` fails (the temporary file is removed).
fn write_atomic_with(path: &Path, write: impl FnOnce(&mut dyn Write) -> Result<(), CliError>) -> Result<(), CliError> {
    let dir = parent_dir(path);
    let io = |what: &str, e: std::io::Error| CliError::Io(format!("{what} '{}': {e}", path.display()));
    let mut tmp = temp_in(&dir).map_err(|e| io("cannot create a temporary file for", e))?;
    {
        let file = tmp.file().map_err(|e| io("cannot write", e))?;
        let mut rec = Recording::new(&mut *file);
        let done = write(&mut rec);
        rec.finish(done, |e| io("cannot write", e))?;
    }
    // Temporary files are private (0600); the output gets the mode a new file would get
    // (0644 here) or keeps the mode of the file it replaces.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(path).map(|m| m.permissions().mode() & 0o7777).unwrap_or(0o644);
        std::fs::set_permissions(&tmp.path, std::fs::Permissions::from_mode(mode)).map_err(|e| io("cannot set permissions of", e))?;
    }
    tmp.file().and_then(|f| f.sync_all()).map_err(|e| io("cannot sync", e))?;
    tmp.persist(path).map_err(|e| io("cannot rename into", e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_are_followed_to_their_file() {
        let dir = tempfile::tempdir().expect("tempdir");
        let d = dir.path();
        std::fs::create_dir(d.join("sub")).expect("mkdir");
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink("sub/t.svg", d.join("a.svg")).expect("symlink");
            std::os::unix::fs::symlink("a.svg", d.join("b.svg")).expect("symlink");
            // Dangling: the file it names is created.
            assert_eq!(resolve(&d.join("b.svg")).ok(), Some(Target::File(d.join("sub/t.svg"))));
            std::fs::write(d.join("sub/t.svg"), b"x").expect("write");
            assert_eq!(resolve(&d.join("b.svg")).ok(), Some(Target::File(d.join("sub/t.svg"))));
            std::os::unix::fs::symlink("loop", d.join("loop")).expect("symlink");
            assert!(resolve(&d.join("loop")).is_err());
        }
        assert_eq!(resolve(&d.join("new.svg")).ok(), Some(Target::File(d.join("new.svg"))));
        assert_eq!(resolve(&d.join("sub")).ok(), Some(Target::Other));
    }

    #[test]
    fn a_file_read_as_an_input_is_never_written_over() {
        let dir = tempfile::tempdir().expect("tempdir");
        let p = dir.path().join("in.png");
        std::fs::write(&p, b"picture").expect("write");
        let dest = Dest::File(p.clone());
        // The control: before it is read, the file may be written over.
        assert!(dest.write(b"first").is_ok());
        assert_eq!(std::fs::read(&p).ok().as_deref(), Some(&b"first"[..]));
        crate::io::read::read_limited(&p, 1 << 10, "a test input").expect("read");
        let e = dest.write(b"second").err().map(|e| (e.exit_code(), e.to_string()));
        assert!(
            e.as_ref().is_some_and(|(code, m)| *code == 2 && m.starts_with("--output: ")),
            "{e:?}"
        );
        assert_eq!(std::fs::read(&p).ok().as_deref(), Some(&b"first"[..]));
        assert_eq!(
            std::fs::read_dir(dir.path()).map(|d| d.count()).ok(),
            Some(1),
            "no temporary file is left"
        );
    }
}
