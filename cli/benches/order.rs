//! Path-order benchmark: time to order real fills of up to 100,000 paths, and pen-up travel
//! against a faithful re-implementation of vpype's `linemerge` + `linesort` (greedy nearest
//! neighbour over line ends, lines may be flipped; circles and polygons are closed lines that
//! start at their first point, as vpype reads them from SVG).
//!
//!     cargo bench -p zetafill-cli --bench order
//!
//! Prints one Markdown table (the README quotes it). Timing is the median of 3 runs.
// Checks may use the platform's maths: only what the tool writes must go through libm.
#![allow(clippy::disallowed_methods)]

use std::time::Instant;
use zetafill_cli::model::fill::{from_fill, BuildOptions};
use zetafill_cli::model::hatch::Hatch;
use zetafill_cli::model::{Drawing, Path, Pt};
use zetafill_cli::output::order::PathOrder;
use zetafill_cli::output::order::{order, PointIndex};

fn fill(args: &[&str]) -> zetafill_cli::model::doc::FillDoc {
    let mut v = vec!["zetafill", "fill", "-q", "-o", "x.json"];
    v.extend_from_slice(args);
    let cli = match <zetafill_cli::Cli as clap::Parser>::try_parse_from(&v) {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    };
    let zetafill_cli::Command::Fill(a) = cli.command else {
        panic!("not fill")
    };
    match zetafill_cli::cmd::fill::compute(
        &zetafill_cli::plan::fill::resolve_as(&a, zetafill_cli::plan::format::Format::Json)
            .unwrap_or_else(|e| panic!("{e}"))
            .0,
    ) {
        Ok((doc, _)) => doc,
        Err(e) => panic!("{e}"),
    }
}

fn dist(a: Pt, b: Pt) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// A line as vpype sees it for ordering: its two ends (equal for closed lines).
fn vpype_ends(p: &Path) -> [Pt; 2] {
    [p.start_point(), p.end_point()]
}

/// vpype `linemerge --tolerance 0.05` (flip allowed): pop the first line, extend its end with
/// the nearest line end within the tolerance, then its start, until none is left.
fn linemerge(lines: &[[Pt; 2]], tol: f64) -> Vec<[Pt; 2]> {
    let items: Vec<(Pt, f64, u32, u32)> = lines
        .iter()
        .enumerate()
        .flat_map(|(i, l)| [(l[0], 0.0, i as u32, 0), (l[1], 0.0, i as u32, 1)])
        .collect();
    let mut index = PointIndex::new(&items);
    let mut used = vec![false; lines.len()];
    let mut out = Vec::new();
    let take = |index: &mut PointIndex, used: &mut Vec<bool>, i: usize| {
        used[i] = true;
        index.remove(index.position(2 * i));
        index.remove(index.position(2 * i + 1));
    };
    for first in 0..lines.len() {
        if used[first] {
            continue;
        }
        take(&mut index, &mut used, first);
        let mut line = lines[first];
        while let Some((pos, d)) = index.nearest(line[1]) {
            if d > tol {
                break;
            }
            let (id, tag) = index.item(pos);
            let other = lines[id as usize];
            take(&mut index, &mut used, id as usize);
            line[1] = if tag == 0 { other[1] } else { other[0] };
        }
        while let Some((pos, d)) = index.nearest(line[0]) {
            if d > tol {
                break;
            }
            let (id, tag) = index.item(pos);
            let other = lines[id as usize];
            take(&mut index, &mut used, id as usize);
            line[0] = if tag == 1 { other[0] } else { other[1] };
        }
        out.push(line);
    }
    out
}

/// vpype `linesort` (flip allowed): the first line stays first; then always the line whose
/// start or end is nearest the pen. Returns pen-up travel from `home`.
fn linesort_travel(lines: &[[Pt; 2]], home: Pt) -> f64 {
    let Some(first) = lines.first() else { return 0.0 };
    let items: Vec<(Pt, f64, u32, u32)> = lines
        .iter()
        .enumerate()
        .skip(1)
        .flat_map(|(i, l)| [(l[0], 0.0, i as u32, 0), (l[1], 0.0, i as u32, 1)])
        .collect();
    let mut index = PointIndex::new(&items);
    let mut travel = dist(home, first[0]);
    let mut pen = first[1];
    while let Some((pos, d)) = index.nearest(pen) {
        let (id, tag) = index.item(pos);
        let l = lines[id as usize];
        travel += d;
        pen = if tag == 0 { l[1] } else { l[0] };
        let k = 2 * (id as usize - 1);
        index.remove(index.position(k));
        index.remove(index.position(k + 1));
    }
    travel
}

fn median_time<T>(mut f: impl FnMut() -> T) -> (T, f64) {
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..3 {
        let t = Instant::now();
        last = Some(f());
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (last.unwrap_or_else(|| unreachable!()), times[1])
}

type Scene = (&'static str, fn() -> Drawing);

fn main() {
    let home = [0.0, 0.0];
    let scenes: [Scene; 4] = [
        ("10^4 circles", || from_fill(&fill(&["--count", "10000"]), &BuildOptions::default())),
        ("10^5 circles", || {
            from_fill(&fill(&["--count", "100000"]), &BuildOptions::default())
        }),
        ("10^5 circles, periodic (clipped arcs)", || {
            from_fill(&fill(&["--count", "100000", "--periodic"]), &BuildOptions::default())
        }),
        ("2000 rotated squares, hatched 0.5 mm", || {
            from_fill(
                &fill(&["--shape", "square", "--count", "2000"]),
                &BuildOptions {
                    hatch: Some(Hatch {
                        spacing: 0.5,
                        angle: 45.0,
                        cross: false,
                    }),
                    ..BuildOptions::default()
                },
            )
        }),
    ];
    // `cargo bench --bench order -- WORD` runs only the drawings whose name holds WORD.
    let filter: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    println!("| drawing | paths | greedy (s) | improved (s) | travel: placement order (mm) | vpype linemerge+linesort (mm) | greedy (mm) | improved (mm) | improved / vpype |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (name, make) in scenes {
        if !filter.iter().all(|f| name.contains(f.as_str())) {
            continue;
        }
        let d = make();
        let n = d.paths.len();
        let none = Drawing { paths: d.paths.clone() }.travel_from(home);
        let ends: Vec<[Pt; 2]> = d.paths.iter().map(vpype_ends).collect();
        let vpype = linesort_travel(&linemerge(&ends, 0.05), home);
        let (g, tg) = median_time(|| order(&d.paths, home, PathOrder::Greedy));
        let (im, ti) = median_time(|| order(&d.paths, home, PathOrder::Improved));
        let greedy = Drawing { paths: g }.travel_from(home);
        let improved = Drawing { paths: im }.travel_from(home);
        println!(
            "| {name} | {n} | {tg:.3} | {ti:.3} | {none:.0} | {vpype:.0} | {greedy:.0} | {improved:.0} | {:.3} |",
            improved / vpype
        );
    }
}
