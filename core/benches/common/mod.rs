//! What the benchmarks share.

use std::time::Instant;

/// The thread's CPU time in seconds (Linux), or the wall time since `start`.
pub fn cpu_seconds(start: Instant) -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next().and_then(|ns| ns.parse::<f64>().ok()))
        .map_or_else(|| start.elapsed().as_secs_f64(), |ns| ns * 1e-9)
}
