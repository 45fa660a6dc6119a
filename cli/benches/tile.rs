//! Fractal tile benchmark (a plain binary, `harness = false`): the time to grow a tile (seed
//! 002's tries against every copy that can reach them) and to make its picture, for discs and
//! cobblestones from a few hundred to about a hundred thousand discs, with the tries per
//! second and the discs placed.
//!
//! Run with `cargo bench -p zetafill-cli --bench tile`. Prints a Markdown table for the
//! README. Measures only; the test suite asserts nothing about time.

use std::time::Instant;
use zetafill_cli::cmd::tile::model::grow;
use zetafill_cli::cmd::tile::render::tile_pieces;
use zetafill_cli::model::tile::{Render, Style, TileSpec};

fn main() {
    println!("| render | radius (mm) | tries | discs | twins | grow (ms) | tries/s | picture (ms) | pieces |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (render, radius, spacing, tries) in [
        (Render::Discs, 5.0, 1.0, 20_000u64),
        (Render::Discs, 1.0, 0.2, 400_000),
        (Render::Discs, 0.3, 0.06, 4_000_000),
        (Render::Voronoi, 2.0, 0.5, 100_000),
        (Render::Voronoi, 0.5, 0.1, 1_000_000),
    ] {
        let spec = TileSpec {
            width: 100.0,
            height: 100.0,
            radius,
            spacing,
            tries,
            seed: 1,
            band: if render == Render::Voronoi { 0.25 } else { 0.0 },
        };
        // The fastest of three runs of each.
        let (mut grow_s, mut pic_s) = (f64::MAX, f64::MAX);
        let (mut tile, mut pieces) = (None, 0);
        for _ in 0..3 {
            let t = Instant::now();
            let g = grow(&spec);
            grow_s = grow_s.min(t.elapsed().as_secs_f64());
            let t = Instant::now();
            let p = tile_pieces(&g, render, Style::Outline).unwrap_or_else(|e| panic!("{e}"));
            pic_s = pic_s.min(t.elapsed().as_secs_f64());
            pieces = p.len();
            tile = Some(g);
        }
        let Some(tile) = tile else { continue };
        println!(
            "| {} | {radius} | {tries} | {} | {} | {:.1} | {:.0} | {:.1} | {pieces} |",
            if render == Render::Voronoi { "voronoi" } else { "discs" },
            tile.discs.len(),
            tile.discs.iter().filter(|d| d.twin.is_some()).count(),
            grow_s * 1e3,
            tries as f64 / grow_s,
            pic_s * 1e3,
        );
    }
}
