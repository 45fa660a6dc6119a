//! Reading input files with a size limit, so that a device or an endless pipe given as an
//! input (`--region svg:/dev/zero`) is refused after a bounded read instead of filling the
//! memory. The limits are documented in docs/cli.md (machine profiles stop at 1 MiB).

use std::io::Read;
use std::path::Path;

/// Largest SVG outline (`--region svg:FILE`).
pub const MAX_SVG_BYTES: u64 = 64 << 20;
/// Largest JSON input (`territory --sites-from`, `stats dimension`): a fill of a million
/// shapes writes about 150 MiB.
pub const MAX_JSON_BYTES: u64 = 1 << 30;

/// The bytes of `path`, or an error if it cannot be read or holds more than `limit` bytes
/// (`what` names the input in that error). Reads at most `limit + 1` bytes, and notes the file
/// as an input of the run, which no output may replace ([`crate::io::inputs`]).
pub fn read_limited(path: &Path, limit: u64, what: &str) -> std::io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    let file = std::fs::File::open(path)?;
    if let Ok(m) = file.metadata() {
        crate::io::inputs::note_read_file(path, &m);
    }
    file.take(limit.saturating_add(1)).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(too_large(limit, what));
    }
    Ok(bytes)
}

/// The error of an input of more than `limit` bytes (`what` names it), as [`read_limited`]
/// gives it.
pub fn too_large(limit: u64, what: &str) -> std::io::Error {
    std::io::Error::other(format!("it holds more than {} MiB, the most {what} may be", limit >> 20))
}

/// The SHA-256 of `bytes` in lower-case hex: how a picture or font input is named in the
/// command that reproduces a file.
pub fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::{Digest, Sha256};
    Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_endless_input_is_cut_off_at_the_limit() {
        let e = read_limited(Path::new("/dev/zero"), 1 << 20, "a test input")
            .err()
            .map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("it holds more than 1 MiB, the most a test input may be"));
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let p = dir.path().join("f");
        std::fs::write(&p, vec![7u8; 1 << 20]).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(read_limited(&p, 1 << 20, "x").map(|b| b.len()).ok(), Some(1 << 20));
        assert!(read_limited(&p, (1 << 20) - 1, "x").is_err());
    }
}
