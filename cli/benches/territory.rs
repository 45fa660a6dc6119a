//! Territory competing benchmark (a plain binary, `harness = false`): points per second and
//! connectivity-repair work per point at 10^4 and 10^5 points, with density control and
//! uniform, plus the time to extract and merge the boundary polylines.
//!
//! Run with `cargo bench -p zetafill-cli --bench territory`. Measures only; the test suite
//! asserts nothing about time.

use std::time::Instant;
use zetafill_cli::cmd::territory::model::{Growth, Model};
use zetafill_cli::cmd::territory::render;
use zetafill_cli::geometry::voronoi::Clip;

fn main() {
    let clip = Clip::Rect {
        x0: 0.0,
        y0: 0.0,
        x1: 200.0,
        y1: 200.0,
    };
    let seeds = [[60.0, 60.0], [140.0, 80.0], [90.0, 150.0]];
    println!(
        "{:>8} {:>8} {:>12} {:>14} {:>12} {:>10} {:>12}",
        "points", "mode", "points/s", "visits/point", "max visits", "repairs", "boundary ms"
    );
    for n in [10_000usize, 100_000] {
        for uniform in [false, true] {
            let reps = if n <= 10_000 { 5 } else { 2 };
            let mut best = f64::MAX;
            let mut last = None;
            for _ in 0..reps {
                let mut m = Model::new(&seeds).unwrap_or_else(|e| panic!("{e}"));
                let g = Growth {
                    points: n,
                    uniform,
                    ..Growth::default()
                };
                let t = Instant::now();
                m.grow(&clip, &g, &mut zetafill::rng_from_seed(1), |_| {})
                    .unwrap_or_else(|e| panic!("{e}"));
                best = best.min(t.elapsed().as_secs_f64());
                last = Some(m);
            }
            let Some(m) = last else { continue };
            let t = Instant::now();
            let lines = render::boundaries(&m, &clip);
            let bms = t.elapsed().as_secs_f64() * 1e3;
            std::hint::black_box(lines);
            let c = m.counters;
            println!(
                "{:>8} {:>8} {:>12.0} {:>14.4} {:>12} {:>10} {:>12.1}",
                n,
                if uniform { "uniform" } else { "density" },
                n as f64 / best,
                c.visited as f64 / n as f64,
                c.max_visited,
                c.repairs,
                bms
            );
        }
    }
}
