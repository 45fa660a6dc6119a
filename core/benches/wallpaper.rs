//! Wallpaper benchmark: what a placement costs with the symmetry of a wallpaper group, against
//! an ordinary periodic fill of the same area. Circles at c = 1.3, N = 1, seed 1, with the cell
//! sampler and the storage the CLI lends (one entry per image, `cells_for` of the entries),
//! for n = 10^4 and 10^5 orbits: a 200 x 200 torus; p1 on the same cell; p4m and p6m on the
//! lattices whose fundamental region has that area (40,000 mm², so every fill places the same
//! sizes). For each it prints a Markdown row: the thread's CPU seconds (fastest of three at
//! 10^4, one run at 10^5), microseconds and trials per placement, and the time over the
//! torus's at the same n. It measures; it asserts nothing about time.
//!
//!     cargo bench -p zetafill --bench wallpaper [-- MAX_N]

use zetafill::{cells_for, Group, Params, Region, Wallpaper};

mod common;
use common::cell_fill_in;

fn main() {
    let max: u64 = std::env::args().skip(1).find_map(|a| a.parse().ok()).unwrap_or(100_000);
    // Sides whose fundamental region is 40,000 mm²: p4m's cell is 8 of them, p6m's 12.
    let p4m = (8.0f64 * 40_000.0).sqrt();
    let p6m = (12.0f64 * 40_000.0 / (3f64.sqrt() / 2.0)).sqrt();
    let cases: [(&str, Region<'static>); 4] = [
        (
            "torus 200 x 200",
            Region::Rect {
                width: 200.0,
                height: 200.0,
                periodic: true,
            },
        ),
        (
            "p1, 200:200:90",
            Region::Wallpaper(Wallpaper::new(Group::P1, 200.0, 200.0, 90.0).expect("a lattice")),
        ),
        (
            "p4m",
            Region::Wallpaper(Wallpaper::new(Group::P4m, p4m, p4m, 90.0).expect("a lattice")),
        ),
        (
            "p6m",
            Region::Wallpaper(Wallpaper::new(Group::P6m, p6m, p6m, 60.0).expect("a lattice")),
        ),
    ];
    println!("| n | fill | images | CPU (s) | us/placement | trials/placement | vs torus |");
    println!("|---:|---|---:|---:|---:|---:|---:|");
    let mut n = 10_000u64;
    while n <= max {
        let mut torus = None;
        for (name, region) in cases {
            let m = region.wallpaper().map_or(1, |w| w.order());
            let cap = n as usize * m;
            let rounds = if n <= 10_000 { 3 } else { 1 };
            let r = (0..rounds)
                .map(|_| cell_fill_in(region, Params::circles(1.3, 1.0), cap, n, cells_for(cap)))
                .min_by(|a, b| a.secs.total_cmp(&b.secs))
                .expect("one round at least");
            let base = *torus.get_or_insert(r.secs);
            let p = r.placed.max(1) as f64;
            println!(
                "| {n} | {name} | {m} | {:.3} | {:.2} | {:.2} | {:.2}x |",
                r.secs,
                r.secs * 1e6 / p,
                r.trials as f64 / p,
                r.secs / base
            );
        }
        n *= 10;
    }
}
