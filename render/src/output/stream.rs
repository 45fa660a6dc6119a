//! An output ready to be written: how to write its bytes into any [`Write`], as often as asked
//! (the same bytes every time), and what is known of its size before a byte is written. The
//! commands stream it into the destination (`cmd::write_output`), so a
//! file never has to fit in memory, and refuse one larger than `--max-output-size` first.
//!
//! The size is known exactly where the format fixes it (a binary STL is 84 bytes and 50 a
//! triangle; a G-code program is counted while its figures are worked out); elsewhere it is
//! bounded from above without formatting anything (every number at its longest), and only
//! when that bound is above the limit does a counting pass ([`Counter`]) find the exact size.
//! A counting pass costs as much as the writing, less the I/O, and is needed only for outputs
//! close to or above the limit.

use crate::error::CliError;
use std::io::Write;

/// The default `--max-output-size`: 4 GiB.
pub const DEFAULT_MAX_OUTPUT_SIZE: u64 = 4 << 30;

/// What is known of an output's size before it is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Size {
    /// Exactly this many bytes.
    Exact(u64),
    /// At most this many bytes.
    AtMost(u64),
}

/// A [`Write`] that keeps nothing and counts the bytes it is given.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Counter(pub u64);

impl Write for Counter {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0 += buf.len() as u64;
        Ok(buf.len())
    }

    fn write_all(&mut self, buf: &[u8]) -> std::io::Result<()> {
        self.0 += buf.len() as u64;
        Ok(())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

type WriteFn<'a> = Box<dyn Fn(&mut dyn Write) -> Result<(), CliError> + 'a>;

/// An output: its size (or a bound on it) and how to write it.
pub struct Output<'a> {
    size: Size,
    write: WriteFn<'a>,
}

impl std::fmt::Debug for Output<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Output").field("size", &self.size).finish_non_exhaustive()
    }
}

impl<'a> Output<'a> {
    /// Bytes already made (a PNG, a GLB, a digest line).
    pub fn bytes(v: Vec<u8>) -> Output<'a> {
        Output {
            size: Size::Exact(v.len() as u64),
            write: Box::new(move |w| w.write_all(&v).map_err(io_error)),
        }
    }

    /// An output written by `write`, whose size is `size`. `write` must write the same bytes
    /// every time it is called.
    pub fn stream(size: Size, write: impl Fn(&mut dyn Write) -> Result<(), CliError> + 'a) -> Output<'a> {
        Output {
            size,
            write: Box::new(write),
        }
    }

    /// What is known of the size.
    pub fn size(&self) -> Size {
        self.size
    }

    /// Writes the bytes into `w` (not flushed).
    pub fn write_to(&self, w: &mut dyn Write) -> Result<(), CliError> {
        (self.write)(w)
    }

    /// The exact size: known, or counted by writing into a [`Counter`].
    pub fn exact_size(&self) -> Result<u64, CliError> {
        match self.size {
            Size::Exact(n) => Ok(n),
            Size::AtMost(_) => {
                let mut c = Counter(0);
                self.write_to(&mut c)?;
                Ok(c.0)
            }
        }
    }

    /// `Ok` when the output has at most `limit` bytes, else `Err` with its exact size. Counts
    /// only when the size is a bound above `limit`.
    pub fn fits(&self, limit: u64) -> Result<Result<(), u64>, CliError> {
        let n = match self.size {
            Size::AtMost(n) | Size::Exact(n) if n <= limit => return Ok(Ok(())),
            _ => self.exact_size()?,
        };
        Ok(if n <= limit { Ok(()) } else { Err(n) })
    }

    /// The bytes, in memory (for callers that need them whole: the browser build, tests).
    pub fn into_bytes(self) -> Result<Vec<u8>, CliError> {
        let mut v = Vec::new();
        self.write_to(&mut v)?;
        Ok(v)
    }
}

pub use crate::error::io_error;

/// Writes `text` pieces through a buffer of about 64 KiB into `out`: for writers that build
/// their text with `push_str` and `write!`.
pub struct TextSink<'w> {
    /// The text not yet handed on.
    pub buf: String,
    out: &'w mut dyn Write,
}

impl<'w> TextSink<'w> {
    const FLUSH_AT: usize = 1 << 16;

    /// A sink into `out`.
    pub fn new(out: &'w mut dyn Write) -> TextSink<'w> {
        TextSink {
            buf: String::with_capacity(Self::FLUSH_AT + 4096),
            out,
        }
    }

    /// Hands the buffer on once it holds 64 KiB or more.
    pub fn maybe_flush(&mut self) -> Result<(), CliError> {
        if self.buf.len() >= Self::FLUSH_AT {
            self.flush()?;
        }
        Ok(())
    }

    /// Hands the whole buffer on.
    pub fn flush(&mut self) -> Result<(), CliError> {
        self.out.write_all(self.buf.as_bytes()).map_err(io_error)?;
        self.buf.clear();
        Ok(())
    }
}

/// A byte count as a message shows it: exact, then in binary units when large
/// (`5368709120 bytes (5 GiB)`).
pub fn bytes_text(n: u64) -> String {
    const UNITS: [&str; 4] = ["KiB", "MiB", "GiB", "TiB"];
    let mut v = n as f64;
    let mut unit = None;
    for u in UNITS {
        if v < 1024.0 {
            break;
        }
        v /= 1024.0;
        unit = Some(u);
    }
    match unit {
        Some(u) => format!("{n} bytes ({} {u})", (v * 10.0).round() / 10.0),
        None => format!("{n} bytes"),
    }
}

/// The refusal of an output of `size` bytes above `limit`: names `--max-output-size`, the
/// size the file would have had, and `advice` (what makes it smaller).
pub fn too_large(what: &str, size: u64, limit: u64, advice: &str) -> CliError {
    CliError::arg(
        "--max-output-size",
        format!(
            "the {what} would be {}, more than the limit of {}: {advice}, or raise --max-output-size",
            bytes_text(size),
            bytes_text(limit)
        ),
    )
}

/// How a refusal names a file of the format `name` (`svg`, `gcode`, ...): `SVG file`,
/// `G-code file`.
pub fn file_of(name: &str) -> String {
    match name {
        "gcode" => "G-code file".into(),
        "digest" => "digest".into(),
        n => format!("{} file", n.to_ascii_uppercase()),
    }
}

/// The longest a shortest-round-trip `f64` is as Rust's `Display` writes it (never an
/// exponent): a sign, `0.`, 323 zeros and up to 17 digits, or 309 integer digits.
pub const MAX_F64_DISPLAY: u64 = 1 + 2 + 323 + 17;

/// The longest a shortest-round-trip `f32` is as Rust's `Display` writes it: a sign, `0.`,
/// 44 zeros and up to 9 digits, or 39 integer digits.
pub const MAX_F32_DISPLAY: u64 = 1 + 2 + 44 + 9;

/// The longest a JSON number is (`serde_json`'s exponent form, at most 24 characters).
pub const MAX_JSON_NUMBER: u64 = 24;

/// The longest a `u64` is in decimal.
pub const MAX_U64: u64 = 20;

/// The number of decimal digits of `n`.
pub fn digits(n: u64) -> u64 {
    n.checked_ilog10().map_or(1, |d| u64::from(d) + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_longest_numbers_are_bounded() {
        let f64s = [
            f64::MIN,
            f64::MAX,
            -f64::MIN_POSITIVE,
            -5e-324,
            -2.2250738585072e-308,
            -1.2345678901234567e-300,
        ];
        for v in f64s {
            assert!(v.to_string().len() as u64 <= MAX_F64_DISPLAY, "{v}");
        }
        let f32s = [f32::MIN, -f32::MIN_POSITIVE, -1e-45, -1.1754942e-38, -1.2345678e-30];
        for v in f32s {
            assert!(v.to_string().len() as u64 <= MAX_F32_DISPLAY, "{v}");
        }
        for v in f64s.into_iter().chain([f64::NAN, -0.0, 1e300]) {
            let mut s = String::new();
            crate::output::number::push_json(&mut s, v);
            assert!(s.len() as u64 <= MAX_JSON_NUMBER, "{s}");
        }
        assert_eq!(u64::MAX.to_string().len() as u64, MAX_U64);
        assert_eq!((digits(0), digits(9), digits(10), digits(u64::MAX)), (1, 1, 2, 20));
    }

    #[test]
    fn a_bound_is_counted_only_above_the_limit() {
        use std::cell::Cell;
        let calls = Cell::new(0);
        let out = Output::stream(Size::AtMost(100), |w| {
            calls.set(calls.get() + 1);
            w.write_all(b"twelve bytes").map_err(io_error)
        });
        assert_eq!(out.fits(100).ok(), Some(Ok(())));
        assert_eq!(calls.get(), 0, "a bound below the limit needs no count");
        assert_eq!(out.fits(50).ok(), Some(Ok(())));
        assert_eq!(out.fits(11).ok(), Some(Err(12)));
        assert_eq!(calls.get(), 2);
        assert_eq!(Output::bytes(vec![0; 7]).fits(6).ok(), Some(Err(7)));
        assert_eq!(bytes_text(5 << 30), "5368709120 bytes (5 GiB)");
        assert_eq!(bytes_text(1000), "1000 bytes");
    }
}
