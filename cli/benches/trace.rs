//! Mask-tracing benchmark (a plain binary, `harness = false`): the time to trace a 4,000 x
//! 4,000 picture into rings with marching squares and to simplify them within half a pixel
//! (crossings repaired), with the vertices before and after simplification.
//!
//! The pictures are made here: a disc field (2,000 discs of radius 10 to 60 pixels, some with
//! a light hole, placed by a fixed linear congruential sequence) and a smooth blob whose
//! outline wobbles round the picture's centre. Run with `cargo bench -p zetafill-cli --bench
//! trace`; prints a Markdown table for docs/performance.md. Measures only; the test suite
//! asserts nothing about time.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

use std::time::Instant;
use zetafill_cli::geometry::{simplify, trace};

const SIDE: usize = 4000;

/// A fixed sequence of numbers in [0, 1).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// 2,000 dark discs (every third with a light hole) on white.
fn discs() -> Vec<f32> {
    let mut luma = vec![1.0f32; SIDE * SIDE];
    let mut rng = Lcg(7);
    for k in 0..2000 {
        let (cx, cy) = (rng.next() * SIDE as f64, rng.next() * SIDE as f64);
        let r = 10.0 + 50.0 * rng.next();
        let hole = if k % 3 == 0 { 0.4 * r } else { 0.0 };
        let (x0, x1) = ((cx - r).max(0.0) as usize, ((cx + r) as usize + 1).min(SIDE));
        let (y0, y1) = ((cy - r).max(0.0) as usize, ((cy + r) as usize + 1).min(SIDE));
        for y in y0..y1 {
            for x in x0..x1 {
                let d = (x as f64 + 0.5 - cx).hypot(y as f64 + 0.5 - cy);
                if d < r && d >= hole {
                    luma[y * SIDE + x] = 0.0;
                }
            }
        }
    }
    luma
}

/// One large blob, its radius wobbling with the angle, grey shades across its rim.
fn blob() -> Vec<f32> {
    let c = SIDE as f64 / 2.0;
    (0..SIDE * SIDE)
        .map(|i| {
            let (x, y) = ((i % SIDE) as f64 + 0.5 - c, (i / SIDE) as f64 + 0.5 - c);
            let t = y.atan2(x);
            let r = 1500.0 + 200.0 * (5.0 * t).sin() + 60.0 * (23.0 * t).cos();
            ((x.hypot(y) - r) / 4.0 + 0.5).clamp(0.0, 1.0) as f32
        })
        .collect()
}

fn main() {
    println!("| picture | rings | vertices traced | vertices simplified | trace (ms) | simplify (ms) |");
    println!("|---|---:|---:|---:|---:|---:|");
    for (name, luma) in [("2,000 discs", discs()), ("one blob", blob())] {
        // The fastest of three runs.
        let (mut t_trace, mut t_simple) = (f64::MAX, f64::MAX);
        let (mut rings, mut before, mut after) = (0, 0, 0);
        for _ in 0..3 {
            let t = Instant::now();
            let raw = trace::trace(&luma, SIDE, SIDE, 0.5, usize::MAX).unwrap_or_default();
            t_trace = t_trace.min(t.elapsed().as_secs_f64());
            let t = Instant::now();
            let simple = simplify::simplify(&raw, 0.5);
            t_simple = t_simple.min(t.elapsed().as_secs_f64());
            (rings, before, after) = (raw.ends.len(), raw.points.len(), simple.points.len());
        }
        println!(
            "| {name} | {rings} | {before} | {after} | {:.0} | {:.0} |",
            t_trace * 1e3,
            t_simple * 1e3
        );
    }
}
